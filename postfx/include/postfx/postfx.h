#pragma once
// postfx: underwater lighting post-process for deferred renderers.
//
//   postfx::CreateDesc createDesc;              // features, G-buffer conventions
//   postfx::Context* fx = nullptr;
//   if (postfx::create(createDesc, fx) != postfx::Result::Ok) log(postfx::lastError(nullptr));
//   ... every frame, after lighting and your underwater fog, before tone mapping:
//   postfx::dispatch(*fx, frameDesc);           // adds light, view-attenuated, into .target
//   ... postfx::stats(*fx).pass(postfx::Pass::Caustics).medianMs   (postfx/diagnostics.h)
// What is added, in which units, and who attenuates it along the view ray:
// FrameDesc::viewExtinction (postfx/frame_desc.h) and docs/integration.md, "Composition in your
// frame".
//   postfx::destroy(fx);
//
// Threading and GL: every call needs the host's GL 4.5 context current on the calling thread.
// create() and destroy() make GL objects with DSA only: no binding changes. dispatch() records GL
// work, saves every piece of GL state it changes and restores it before returning; it never
// reads back or waits on the GPU. Any host state gives the same image: every fixed-function
// state that changes what a draw writes (logic op, multisample and sample coverage/mask,
// rasterizer discard, polygon mode and offset, clip distances and clip control, depth and
// stencil, depth clamp, framebuffer sRGB, primitive restart, provoking vertex, blend colour,
// dither, smoothing, per-draw-buffer blend and colour masks, scissor per viewport, point sprite
// origin) is set for the plugin's own draws and restored. Active (unpaused) transform feedback
// is refused (InvalidArgument). Conditional rendering cannot be queried in GL 4.5: inside it
// the plugin's draws are subject to the host's query, so do not call dispatch() there.
// The library never prints, aborts or throws.
#include <cstdint>

#include <postfx/diagnostics.h>
#include <postfx/frame_desc.h>
#include <postfx/lights.h>
#include <postfx/local_water.h>
#include <postfx/result.h>
#include <postfx/settings.h>

namespace postfx {

// Decided at create(): each becomes a shader #define, so a feature that is off costs nothing.
enum class Feature : std::uint32_t {
  None = 0,
  Caustics = 1u << 0,        // seabed caustics (CausticsSettings)
  GodRays = 1u << 1,         // underwater light shafts (GodRaySettings)
  ObjectCaustics = 1u << 2,  // caustics of glass/metal casters (postfx/casters.h, lights.h)
  Dispersion = 1u << 3,      // per-channel IOR (WaterSurface::iorRgb): coloured caustic edges
  ShadowMask = 1u << 4,      // mask caustics by the host's sun shadow map (FrameDesc::shadow)
  // 1u << 5 and 1u << 6: test and benchmark hooks, postfx/testing.h.
  WavefrontAreaRatio = 1u << 7,  // allows CausticsModel::WavefrontAreaRatio; its pass
                                 // is timed as Pass::WavefrontAreaRatio
  // Full tri-planar water lookup: steep surfaces (more than ~30 degrees from horizontal at the
  // default CausticsSettings::triplanarSharpness) also sample the water along the world x and
  // z axes, blended by the G-buffer normal (three times the fetches there). Without it every
  // surface samples the water where its light entered, along the refracted sun: one
  // projection, seamless across floor, walls and overhangs, at a third of the fetches.
  TriplanarWalls = 1u << 8,
  // Local water regions (WaterSurface::localWater, postfx/local_water.h): their light, computed
  // once per frame for every view, timed as Pass::LocalWater. Without it no shader reads them.
  LocalWater = 1u << 9,
  // Reflected caustics above the water (FrameDesc::reflectedCaustics,
  // postfx/reflected_caustics.h), timed as Pass::ReflectedCaustics. Without it nothing above the
  // level receives light from the plugin's seabed passes.
  ReflectedCaustics = 1u << 10,
  // The light the object casters focus, seen in the water (ObjectCausticsSettings::volume,
  // postfx/casters.h): every traced ray's in-scattered light along its way from the caster to
  // where it lands, drawn after each light's object caustics and timed with them. Needs
  // Feature::ObjectCaustics; reads the god rays' phase, fades and maxDistance (GodRaySettings,
  // validated with this feature even without Feature::GodRays).
  VolumeCaustics = 1u << 11,
  // 1u << 12 and 1u << 13: testing hooks, postfx/testing.h.
  // Former name, kept so that a host compiles while it renames (CHANGELOG.md).
  PhysicalCaustics [[deprecated("renamed Feature::WavefrontAreaRatio")]] = WavefrontAreaRatio,
};
constexpr Feature operator|(Feature a, Feature b) {
  return static_cast<Feature>(static_cast<std::uint32_t>(a) | static_cast<std::uint32_t>(b));
}
constexpr bool hasFeature(Feature set, Feature f) {
  return (static_cast<std::uint32_t>(set) & static_cast<std::uint32_t>(f)) != 0;
}

enum class WaterTextureType {
  Array2D,  // GL_TEXTURE_2D_ARRAY, one layer per cascade (the water module's output)
  Single2D  // GL_TEXTURE_2D, exactly one cascade
};

struct CreateDesc {  // fixed for the context's life
  Feature features = Feature::Caustics;
  DepthConvention depthConvention = DepthConvention::ReverseZ;  // of FrameDesc::depth
  NormalEncoding normalEncoding = NormalEncoding::Octahedral;   // of FrameDesc::normal
  WaterTextureType waterTexture = WaterTextureType::Array2D;
  // Most water cascades a frame will give (WaterSurface::cascadeCount <= this), [1,
  // kMaxCascades]; ignored with Single2D (one). Each slot is a lookup written into the shaders:
  // a rasteriser that runs both arms of a branch (CPU, e.g. llvmpipe) pays for unused slots, a
  // GPU does not.
  int maxWaterCascades = kMaxCascades;
  // GPU memory (MiB) the context may allocate for a frame, [1, 1048576]: the textures and
  // buffers sized by the frame (raw output, god-ray march texture, irradiance layers, caster
  // maps, the object caustic map and its history). A frame whose settings need more is refused
  // with Result::OutOfMemory before anything is allocated or drawn. The default holds every
  // default setting many times over (the object caustics' default map 512 needs 12 MiB); a
  // caustic map of 4096 needs 768 MiB, 8192 needs 3 GiB, 16384 needs 12 GiB.
  int memoryBudgetMiB = 1024;
  // Work the object caustics may record in a frame (Feature::ObjectCaustics), counted on the
  // CPU with the memory: a frame over either budget is refused with InvalidArgument naming it
  // before anything is drawn, rather than stalling the GPU. Each in [1, 2^40].
  //   casterTriangleBudget: triangles drawn into the caster maps, each caster's (indexCount
  //     / 3, or vertexCount / 3) twice (front and back faces) for every view that draws it:
  //     the sun's and each local light's that reaches it. The default is 32M caster triangles
  //     seen from the sun, a few seconds a frame on a CPU rasteriser (llvmpipe).
  //   splatBudget: splats drawn into the caustic maps, ObjectCausticsSettings::gridSize^2 per
  //     view, three times that when a caster is dispersed (Feature::Dispersion); each covers
  //     at most 137 x 137 map texels. The default holds gridSize 2048 from 8 views, or with
  //     dispersion from 2.
  std::int64_t casterTriangleBudget = std::int64_t(1) << 26;
  std::int64_t splatBudget = std::int64_t(1) << 25;
  // Most local lights a frame may list (ObjectCausticsFrame::lightCount), [0,
  // kMaxLocalLightsLimit] (postfx/lights.h), fixed at create(): it sizes the uniform blocks
  // (one 3664-byte block per light, 3.75 KiB at a 256-byte offset alignment) and the
  // per-light timers. A light runs the sun's own programs with its own block, so no shader is
  // compiled per light and 0 (default) costs nothing. Read only with Feature::ObjectCaustics.
  int maxLocalLights = 0;
  // The work account (postfx/diagnostics.h: PassStats::work, workSteps()): each draw and
  // dispatch counted by the driver's pipeline-statistics and samples-passed queries, read back
  // with the timings, never waited for. Off by default: five queries per draw or dispatch.
  bool workAccount = false;
};

struct Context;  // opaque

// Builds the programs and GL objects for `desc`. On failure `out` is null and
// lastError(nullptr) explains why.
Result create(const CreateDesc& desc, Context*& out) noexcept;

// Adds this frame's light into desc.target. Every input is validated before any GL state is
// touched: on error nothing is drawn and GL state is exactly as it was. The passes run in the
// order of the Pass enum (postfx/diagnostics.h; every pass, its inputs, outputs and settings:
// docs/passes.md), each timed in stats().pass(Pass::...); a pass with nothing to do is skipped
// and reports 0 ms. The model's pre-passes (Pass::TileIrradiance for TileIrradiance and
// WavefrontAreaRatio, Pass::WavefrontAreaRatio for the latter's window) run when Pass::Caustics
// or Pass::GodRays draws. Pass::Caustics and Pass::GodRays (Feature::GodRays; below full
// resolution the march and the upsample together) are skipped when disabled, with the sun
// at/below the horizon, or with no part of the view frustum below the water level;
// Pass::GodRays also at godRays.intensity 0. Pass::ObjectCaustics (the sun's,
// Feature::ObjectCaustics) is skipped with no caster, objectCaustics.settings.enabled off or
// intensity 0, sunCaustics off, the sun at/below the horizon, or no caster inside the receiver
// map's view; then each local light (postfx/lights.h) that reaches a caster runs, timed in
// stats().objectLight(i).
Result dispatch(Context& context, const FrameDesc& desc) noexcept;

// Deletes the context's GL objects (current GL context required; without one they are leaked
// rather than abort the process). Null is a no-op.
void destroy(Context* context) noexcept;

// lastError() and stats(): postfx/diagnostics.h.

// With Feature::ObjectCaustics: the caustic map of the last dispatch that ran the pass, for
// hosts that composite it themselves (forward passes, water volumes) and for tests. A
// plugin-owned GL_RGBA32F GL_TEXTURE_2D; rgb = caustic irradiance over the sun's (1 = the sun's
// unobstructed irradiance on a surface facing it), before albedo and N.L. A world point p maps to
// texel coordinates ((p - origin) . axisU / |axisU|^2, (p - origin) . axisV / |axisV|^2) * size,
// projected along `direction`. texture is 0 before the first such dispatch.
struct ObjectCausticMap {
  GlName texture = 0;
  int size = 0;
  glm::dvec3 origin{0.0};                // world position of the map's (0, 0) corner
  glm::dvec3 axisU{0.0}, axisV{0.0};     // world vectors spanning the map along u and v
  glm::dvec3 direction{0.0, -1.0, 0.0};  // unit direction the light travels (refracted under water)
};
ObjectCausticMap objectCausticMap(const Context& context) noexcept;

}  // namespace postfx

// Several views per frame (split-screen, stereo, cube-map probes): postfx/views.h.
#include <postfx/views.h>
