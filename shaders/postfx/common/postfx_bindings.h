// Where the plugin's passes bind what their shaders read, and the bounds and constants both sides
// must agree on. Compiled by C++ (the passes bind, GlStateGuard saves and restores) and by GLSL
// (layout qualifiers, loop bounds), so each unit is named once. Units and bindings are macros:
// GLSL layout qualifiers and C++ GL calls both take them as they are.
#ifndef POSTFX_SHARED_BINDINGS_H
#define POSTFX_SHARED_BINDINGS_H
#include "shared/common.h"

// Texture units of the caustics pass's state (CausticsPass::bindState), which the floor, the god
// rays and both irradiance pre-passes draw under.
#define POSTFX_UNIT_DEPTH 0
#define POSTFX_UNIT_NORMAL 1
#define POSTFX_UNIT_ALBEDO 2
#define POSTFX_UNIT_WATER 3
#define POSTFX_UNIT_SHADOW 4
// The WavefrontAreaRatio model's irradiance window.
#define POSTFX_UNIT_IRRADIANCE 5
// The god rays' reduced-resolution march, read by their upsample: it reuses the irradiance unit,
// whose reader (the caustics pass) has drawn by then.
#define POSTFX_UNIT_GODRAYS_REDUCED 5
// The TileIrradiance lookups at half resolution, read by the caustics pass's upsample: the
// window's irradiance unit, unused in that model's frames (the reduced lookups read the tile
// field on its own unit).
#define POSTFX_UNIT_TILE_REDUCED 5
// The WavefrontAreaRatio pre-pass's grid points (a buffer texture).
#define POSTFX_UNIT_GRID_POINTS 6
// The TileIrradiance field (that model's light, and the WavefrontAreaRatio model's beyond its
// window, so both are bound at once): it reuses the grid points' unit on its 2D-array target,
// whose reader (the irradiance pre-pass) has drawn by then.
#define POSTFX_UNIT_TILE_IRRADIANCE 6
// Local water (Feature::LocalWater): the regions' irradiance layers (one texture for all), read
// by the caustics and the god rays;
// the region's host surface, read by its pre-pass only, on the window's irradiance unit (its
// reader, the caustics pass, binds it again after the pre-passes).
#define POSTFX_UNIT_LOCAL_WATER 7
#define POSTFX_UNIT_LOCAL_SURFACE 5
// Units [0, POSTFX_UNIT_COUNT) are the ones GlStateGuard saves and restores.
#define POSTFX_UNIT_COUNT 8

// The object caustics pass binds its own units (under its own state), consecutive from 0:
// the ray trace reads the caster maps and the receiver depth,
#define POSTFX_OBJECT_UNIT_FRONT_POSITION 0
#define POSTFX_OBJECT_UNIT_FRONT_NORMAL 1
#define POSTFX_OBJECT_UNIT_BACK_POSITION 2
#define POSTFX_OBJECT_UNIT_BACK_NORMAL 3
#define POSTFX_OBJECT_UNIT_SPLAT_RECEIVER_DEPTH 4
// (the ray trace reads those five too), the splat where the trace found each ray lands,
#define POSTFX_OBJECT_UNIT_LANDINGS 5
// The volume caustics' summed light, added to the target (volume_caustics_resolve.frag).
#define POSTFX_OBJECT_UNIT_VOLUME_LIGHT 6
// the temporal filter this frame's splats and the filtered history,
#define POSTFX_OBJECT_UNIT_CURRENT_MAP 0
#define POSTFX_OBJECT_UNIT_HISTORY_MAP 1
// and the composite the host's G-buffer (the caustics pass's units 0-2), the map and the
// receiver depth.
#define POSTFX_OBJECT_UNIT_CAUSTIC_MAP 3
#define POSTFX_OBJECT_UNIT_RECEIVER_DEPTH 4

// Shader-storage bindings and image units; each pre-pass binds its own before it dispatches.
#define POSTFX_STORAGE_GRID_POINTS 0  // WavefrontAreaRatio: the compute step's output
#define POSTFX_STORAGE_CLAMP_COUNT 0  // WavefrontAreaRatio: the draws' clamp counter
#define POSTFX_STORAGE_TILE_ACCUMULATORS 0
// The tile irradiance's unresolved-slope spread: its blur's two copies of the layers, and the
// slope statistics that the blur reads.
#define POSTFX_STORAGE_TILE_BLUR 1
#define POSTFX_STORAGE_TILE_SPREAD 2
#define POSTFX_IMAGE_TILE_IRRADIANCE 0  // the TileIrradiance resolve's output
#define POSTFX_IMAGE_OBJECT_LANDINGS 0  // the object caustics' ray trace output

SHARED_BEGIN

// Most samples one god-ray march takes: the shader's loop bound, and the top of
// kGodRaySampleCountRange (godrays_constants.cpp checks the two agree).
SHARED_CONST int GODRAYS_MAX_SAMPLES = 64;
// The WavefrontAreaRatio window's outer band (fraction of its side) over which its irradiance
// fades to the TileIrradiance field's (the RayDeviation model's without a water texture).
SHARED_CONST float IRRADIANCE_FADE_BAND = 0.125f;
// Mip levels above the base of the WavefrontAreaRatio irradiance layers (the lookup filters a
// pixel's footprint); the window snaps to texels of the coarsest, and its fade is taken from a
// camera-centred window that much smaller, so that the fade moves smoothly with the camera.
SHARED_CONST int IRRADIANCE_MIP_LEVELS = 4;

SHARED_END

#endif
