#pragma once
// Hooks for tests, benchmarks and the report: not part of what a host integrates, and not
// included by postfx/postfx.h. Nothing here changes what a frame without them looks like.
#include <cstdint>

#include <postfx/postfx.h>

namespace postfx::testing {

// Create-time features beside the host's (CreateDesc::features | testing::BenchmarkFloor).
//  - RawCausticOutput: the caustics pass also writes its raw factor to rawCausticTexture().
//  - BenchmarkFloor: a "floor" pass (Pass::Floor) runs whenever any timed pass runs (after the
//    caustics model's pre-passes, before Pass::Caustics): a full-screen pass that reads the
//    G-buffer, the water cascades (when a water texture is given) and the shadow map and
//    writes the same outputs with no math (adds exactly 0), so that a pass's medianMs over the
//    floor's measures its cost independently of the machine. The GPU is drained before each
//    timed pass (glFinish): never in a shipping frame.
inline constexpr Feature RawCausticOutput = static_cast<Feature>(1u << 5);
inline constexpr Feature BenchmarkFloor = static_cast<Feature>(1u << 6);
// With CreateDesc::workAccount: every program counts its own invocations, texture fetches and
// atomics, so that the work account's are exact (WorkSource::kWorkCounted), and each draw or
// dispatch's counters are read back at once (the GPU is waited for: never in a shipping frame;
// the frame's timings then include the counting). Without workAccount it does nothing.
inline constexpr Feature CountShaderWork = static_cast<Feature>(1u << 12);
// With CreateDesc::workAccount: the GPU is drained before and after every step, and the step's
// time by the CPU's clock kept (WorkStep::drainedMs): a step's own cost on a CPU rasteriser,
// where the timer queries of a pass cannot separate its draws. The account's queries are left
// out (they slow such a rasteriser's draws): its counts are the draw and dispatch sizes only.
// Never in a shipping frame.
inline constexpr Feature TimeEachStep = static_cast<Feature>(1u << 13);

// With RawCausticOutput: a plugin-owned GL_R16F GL_TEXTURE_2D the size of the last dispatched
// target holding omega * (n.l) * shadow * fade (mean of R,G,B): the caustic factor with N.L,
// the shadow map and the surface fade, before albedo, irradiance, intensity and absorption
// (flat water reads n.l, not 1); 0 where no caustics (sky, above water, back-facing, shadowed,
// pass skipped). Range of omega, per CausticsSettings::model, with c = min(maxIrradiance, 1024):
//  - TileIrradiance (the default): the product of the cascades' fields, each in [0, c]:
//    [0, min(c^k, 1024)], k the cascades with irradiance (defaults: c = 32);
//  - WavefrontAreaRatio: [0, maxIrradiance] inside the window, TileIrradiance's range where it
//    fades to the tile field (outer eighth and beyond);
//  - RayDeviation: [0, 1].
// A GL_R16F texel holds at most 65504. 0 without the feature or before the first dispatch.
GlName rawCausticTexture(const Context& context) noexcept;
// The same for a view of a multi-view dispatch (postfx/views.h): its own raw output, the size of
// its target, written inside its viewport (0 outside it). rawCausticTexture(context) is the
// plain dispatch(context, frame)'s.
GlName rawCausticTexture(const View& view) noexcept;
// The GPU memory a view holds (its raw output and reduced-resolution textures), in bytes.
std::uint64_t viewAllocatedBytes(const View& view) noexcept;

// The WavefrontAreaRatio model's irradiance of the most recent frame that computed it.
struct CausticIrradianceInfo {
  // Plugin-owned GL_TEXTURE_2D_ARRAY, GL_R32F, resolution^2 texels x layers: irradiance on a
  // horizontal receiver relative to flat water (flat water gives 1), clamped, no absorption.
  // 0 without Feature::WavefrontAreaRatio or before the first frame in that model.
  GlName texture = 0;
  int resolution = 0, layers = 0;
  glm::dvec2 windowOrigin{0.0};  // world xz of the corner of texel (0, 0) (m)
  double windowSize = 0.0;       // m; texel (i, j) covers origin + [i, i+1) * size / resolution
  float layerDepth[8] = {};      // m below the water level, per layer
};
CausticIrradianceInfo causticIrradiance(const Context& context) noexcept;

// With Feature::ObjectCaustics: the caustic map of the last local light the last dispatch drew
// (one map serves every light in turn). A plugin-owned GL_RGBA32F GL_TEXTURE_2D of size^2 texels
// in the light's perspective view; rgb = the caustic irradiance per unit of the light's
// intensity (1/m^2; multiply by LocalLight::intensity * settings.intensity for the host's
// units) on a surface facing the light, where the light lands after the casters: cone,
// Fresnel, transmission, absorption and the inverse square included, before albedo and N.L. A
// world point p maps to texel ((c.xy / c.w) * 0.5 + 0.5) * size, c = worldToMapClip * (p, 1).
// texture is 0 before the first light is drawn.
struct LightCausticMap {
  GlName texture = 0;
  int size = 0;
  glm::dmat4 worldToMapClip{1.0};
};
LightCausticMap lightCausticMap(const Context& context) noexcept;

// How the god-ray march places its samples along each view ray.
enum class GodRaySampling {
  // What every context does: where the ray crosses the planes of a world-snapped grid, so the
  // samples stay put in the world when the camera moves.
  WorldGrid,
  // sampleCount points evenly spread along the ray: slides with the camera (flickers). For
  // comparisons (the temporal-stability test, the report) only.
  UniformAlongRay,
};
// Sets the sampling of the context's later frames; InvalidArgument (nothing changed) for a
// value outside the enum.
Result setGodRaySampling(Context& context, GodRaySampling sampling) noexcept;
// Where within each of its steps UniformAlongRay puts a sample, in [0, 1) (0.5, the middle,
// unless set; the dither, when on, overrides it): the mean of frames at evenly spread phases is a
// march with that many times the samples (the report's dense march of the god rays).
// InvalidArgument (nothing changed) outside [0, 1).
Result setGodRayUniformPhase(Context& context, float phase) noexcept;

}  // namespace postfx::testing
