#pragma once
// Per-frame tuning of the caustics, a plain struct with defaults. Every float must be finite
// and inside its range (the k...Range constants, which validation uses), or dispatch() returns
// InvalidArgument and draws nothing.
#include <postfx/range.h>

namespace postfx {

// What the caustics pass multiplies the sun light by.
enum class CausticsModel {
  // omega = exp(-tau a^2), a the sine of the angle between the sun ray refracted (and
  // reflected) by the local water normal and its flat-water ray (with the
  // whole deviation rather than its component across the plane of incidence, which streaked
  // the pattern along the sun's azimuth). One texture lookup per cascade and pixel, any receiver
  // shape; a pattern without absolute scale (flat water gives 1, waves only darken).
  RayDeviation,
  // True caustic irradiance from the wavefront area ratio. Every frame a grid over
  // the water surface is refracted onto a few receiver depths and its triangles are added up
  // (folds sum) with brightness = beam area / refracted area. Needs Feature::PhysicalCaustics.
  // Covers a camera-centred square window (windowSize); outside it, and across the window's
  // outer eighth, it fades to the TileIrradiance field (same physics and units: no edge), which
  // it computes too. A pixel smaller than a texel gets a smooth (cubic B-spline) reconstruction
  // of the window, not its texel grid; a larger one the mean over its footprint.
  WavefrontAreaRatio,
  // True caustic irradiance everywhere, at about the cost of RayDeviation: every frame each
  // cascade that can focus light within maxReceiverDepth refracts its own periodic tile onto
  // tileDepthLayers depths (small compute dispatches: scatter, resolve and one per mip level,
  // tileResolution^2 texels, independent of the screen). A pixel multiplies one filtered lookup
  // per cascade, each moved by the coarser cascades' refraction (their light lands displaced).
  // Any receiver shape and distance, no window, no edge; mip-filtered, so far pixels get their
  // footprint's mean light. The product of per-cascade fields is an approximation of refracting
  // through their sum: close where the cascades' scales are far apart, too contrasty where two
  // cascades focus near the receiver's depth (measured: docs/measurements.md, "The pattern
  // alone"). Its receivers should lie within maxReceiverDepth, whose depth layers it
  // interpolates between.
  TileIrradiance,
  Seed002 [[deprecated("named for a paper: use RayDeviation")]] = RayDeviation,
};

inline constexpr Range<float> kTauRange{0.0f, 1e6f};
inline constexpr Range<float> kUnitRange{0.0f, 1.0f};
inline constexpr Range<float> kIntensityRange{0.0f, 1e4f};
inline constexpr Range<float> kFadeDepthRange{0.0f, 1e4f};  // m
inline constexpr Range<float> kTriplanarSharpnessRange{1.0f, 32.0f};
inline constexpr Range<float> kLodBiasRange{-4.0f, 8.0f};  // mip levels
inline constexpr Range<int> kGridResolutionRange{64, 1024};
inline constexpr Range<float> kWindowSizeRange{1.0f, 1e4f};  // m
inline constexpr Range<int> kDepthLayersRange{1, 8};
inline constexpr Range<float> kMaxReceiverDepthRange{0.01f, 1e4f};  // m
inline constexpr Range<float> kMaxIrradianceRange{1.0f, 1e4f};
inline constexpr Range<int> kTileResolutionRange{32, 1024};  // and a power of two

// Where TileIrradiance looks its irradiance up. Its four filtered fetches per pixel (two
// cascades' light and the slopes that move it) are most of its cost on a CPU rasteriser; the
// light they give varies on the scale of the caustic network, several pixels wide at any
// distance (the lookup is filtered over the footprint).
enum class CausticsLookupResolution {
  Full = 1,  // every pixel
  // Every other pixel in x and y into a plugin-owned texture (irradiance and distance as halves),
  // blended back per pixel by bilinear weight times distance similarity, so no light bleeds
  // across silhouettes; everything else (normal, shadow, albedo, absorption) stays per pixel.
  Half = 2,
};
inline constexpr Range<float> kTileMinModulationRange{0.0f, 1e3f};

struct CausticsSettings {
  // Off: the pass is skipped (0 ms) and, with RawCausticOutput, the raw texture reads 0.
  bool enabled = true;

  // RayDeviation only (validated always; TileIrradiance and WavefrontAreaRatio ignore it, bit
  // for bit, seabed and god rays alike): tightening τ of ω = exp(-τ·a²),
  // unitless, kTauRange. Larger values give thinner, sharper caustic lines; 0 gives ω = 1
  // everywhere (uniform light).
  float tau = 800.0f;

  // RayDeviation only, like tau: blend of the reflected ray's ω into the refracted one's,
  // kUnitRange: 0 = refraction only.
  float reflectionWeight = 0.25f;

  // Multiplier on the sun's irradiance for the added caustic light, kIntensityRange. The light
  // added is a copy of the direct underwater sun without 1/pi and surface Fresnel
  // (docs/integration.md,
  // "Composition in your frame"): (1 - F) / pi replaces a Lambertian direct sun exactly.
  float intensity = 1.0f;

  // Depth below the water level (m) over which caustics ramp in from 0 at the surface, where the
  // refracted rays have not focused yet, to full strength, kFadeDepthRange. 0 = no fade.
  float surfaceFadeDepth = 1.0f;

  // With Feature::TriplanarWalls: exponent sharpening the tri-planar weights |n|^k taken from
  // the G-buffer normal, kTriplanarSharpnessRange. High values make each surface use the single
  // projection it faces most (fewest fetches on GPUs). Validated always, unused without the
  // feature.
  float triplanarSharpness = 8.0f;

  // Added to the water-texture mip level chosen from each pixel's footprint, in mip levels,
  // kLodBiasRange. Positive blurs earlier with distance, which hides tile repetition sooner.
  float lodBias = 0.0f;

  // Cascades whose first-order irradiance modulation at a receiver's depth
  // (WaterSurface::rmsLaplacian) is below this are not sampled there; the ones between it and
  // twice it fade in. kUnitRange; 0 samples every cascade everywhere. Also applies to the god rays.
  // Each cascade skipped saves one filtered water fetch per pixel on a GPU, where a warp whose
  // pixels all skip it branches around it (a CPU rasteriser such as llvmpipe runs it masked and
  // saves nothing); the error it costs is in the report (ocean_sample report).
  float minCascadeContrast = 0.1f;

  // The light field of the seabed caustics and of the god rays (GodRaySettings): with
  // TileIrradiance and WavefrontAreaRatio the shafts take their light from the same irradiance
  // as the seabed, so they line up with its pattern; the field's pre-pass then runs whenever
  // either draws (god rays alone included) and is left out when neither does.
  CausticsModel model = CausticsModel::TileIrradiance;

  // --- TileIrradiance only (validated always) ---
  // Irradiance texels per side of each cascade's tile, a power of two in kTileResolutionRange.
  // GPU memory:
  // tileResolution^2 * (8 bytes * 4/3 + 4 bytes) * tileDepthLayers / 4 per cascade with
  // waves that focus (128, 4 layers: 0.44 MB per cascade). A host whose cascade holds waves
  // only a few texels long (ripples in a coarse tile) needs more: docs/measurements.md,
  // "A host's own water"; finer than its waves need makes the pattern too sharp. Where
  // tileResolution * tilePointsPerTexel reaches the water texture's side (nothing unresolved
  // is left to soften the light), each point's flux covers its refracted cell, up to 4 texels
  // wide, rather than a bilinear texel square: diverging light stays smooth, not a grid of
  // dots (the pre-pass about 2x slower on a CPU rasteriser).
  int tileResolution = 128;
  // Refracted water points per irradiance texel and side, 1 or 2: each point carries the mean
  // slope and height of its cell of the water texture (the mip level of the cell's size). 2
  // quadruples the pre-pass for a smoother density where light converges; at the defaults the
  // default preset's error is in docs/measurements.md for both.
  int tilePointsPerTexel = 1;
  // Depth layers per cascade, 4 or 8: one or two filtered fetches per cascade and pixel.
  int tileDepthLayers = 4;
  // Cascades whose first-order irradiance modulation at maxReceiverDepth
  // (WaterSurface::rmsLaplacian) is below this get no irradiance of their own,
  // kTileMinModulationRange: their
  // long waves barely focus there, they only move the finer cascades' light (which is kept).
  // Each one left out saves a fetch per pixel and a third of the pre-pass.
  float tileMinModulation = 0.25f;
  // Each cascade's irradiance is convolved, per depth layer, with the landing spread of the
  // slopes its points do not resolve (inside a point's cell of the water texture, and every
  // finer cascade's): those ripples, shorter than the pattern and far past their own focus at
  // depth, scatter the light like a diffuser, softening the pattern by depth * J * slope spread
  // (J the landing drift, about (1 - 1/n) / cos for a high sun). Measured from the water texture
  // every frame (any host's water); its error and cost: docs/measurements.md. Off: the pattern
  // of the points alone, sharper than the light the water really sends, with rings where a
  // coarser cascade focuses a finer one's pattern (the pre-pass 0.2x cheaper on llvmpipe).
  bool tileUnresolvedSpread = true;
  // Resolution of the lookups (see CausticsLookupResolution). Half costs a quarter of the
  // lookups plus a 4-tap upsample and 4 bytes per reduced texel (0.9 MB at 1280x720); its
  // accuracy and cost against Full are in docs/measurements.md.
  CausticsLookupResolution tileLookupResolution = CausticsLookupResolution::Half;

  // --- WavefrontAreaRatio only (validated always) ---
  // Surface grid vertices per side and irradiance texels per side, kGridResolutionRange. Cost grows
  // with its square; the water texture is read at the mip level of the grid spacing, so ripples
  // finer than windowSize * 1.25 / gridResolution are smoothed away, not aliased. GPU memory:
  // R32F layers, 4 bytes x depthLayers per texel with up to 4 mip levels (x 1.33), plus 32 bytes
  // per grid point ((gridResolution + 2)^2 points); 4 layers: 0.85 MiB at 128, 3.36 MiB at 256,
  // 13.4 MiB at 512, 53.4 MiB at 1024. The tile irradiance that continues the window (see
  // windowSize) adds its own (tileResolution: 0.42 MiB per cascade at 128, 4 layers).
  int gridResolution = 256;
  // Side of the square receiver window around the camera (m), kWindowSizeRange. Snapped to whole
  // texels in world space so the pattern does not swim when the camera moves. Beyond it, faded in
  // over its outer eighth, the light is the TileIrradiance model's (the same irradiance, periodic,
  // without a window): that pre-pass also runs in this model's frames.
  float windowSize = 32.0f;
  // Receiver depths the irradiance is computed at, kDepthLayersRange: layer k lies
  // maxReceiverDepth * ((k + 1) / depthLayers)^2 below the level (denser near the surface,
  // where the pattern changes fastest with depth). A pixel interpolates linearly in depth
  // between the two layers around it (between 1 at the surface and layer 0 above it; the
  // deepest layer below it).
  int depthLayers = 4;
  // Deepest receiver layer (m), kMaxReceiverDepthRange, also TileIrradiance's (its layers lie
  // at maxReceiverDepth * ((k + 1) / tileDepthLayers)^1.5). Deeper receivers get its light.
  float maxReceiverDepth = 16.0f;
  // Irradiance clamp relative to flat water, kMaxIrradianceRange (TileIrradiance too; it stores
  // at most 1024). Folds focus to infinite irradiance on a triangle of zero area; the clamp
  // bounds that. The flux it removes is reported as FrameStats::clampedFluxFraction (a bias
  // figure; WavefrontAreaRatio only).
  float maxIrradiance = 32.0f;
};

}  // namespace postfx

namespace postfx {

// Resolution the god-ray march runs at. Below full, each texel of a plugin-owned texture (8 bytes:
// light and distance as halves) marches the ray of the top-left pixel of its block, and a
// depth-aware (bilateral) upsample adds the result into the target; shafts are soft, so the
// lost detail costs little accuracy (the report measures it) for 1/4 or 1/16 of the march.
enum class GodRayResolution {
  Full = 1,
  Half = 2,     // 1/4 of the march cost
  Quarter = 4,  // 1/16 of the march cost; the finest shafts softer (the default)
};

// Per-frame tuning of the god rays (Feature::GodRays), a plain struct with defaults. Every float
// must be finite and inside its documented range, or dispatch() returns InvalidArgument and
// draws nothing. The light they add is in-scattered sunlight (see godrays.frag for the model):
//   L = E_sun * intensity * sigma_s / sigma_t * (1 - exp(-sigma_t * D)) * gamma,
// gamma the seed's eq. (2) average of rho_i * omega_i along the ray (weighted by each sample's
// segment length and view-path transmittance), in [0, 1]; sigma_* from WaterSurface.
inline constexpr Range<int> kGodRaySampleCountRange{4, 64};
inline constexpr Range<float> kGridSpacingRange{0.01f, 1e3f};       // m
inline constexpr Range<float> kDepthFadeDistanceRange{0.0f, 1e5f};  // m
inline constexpr Range<float> kMaxMarchDistanceRange{0.1f, 1e5f};   // m

// Single scattering of the sun along each view ray under the water. The light at each sample is
// the caustics model's field at the sample's depth (CausticsSettings::model): TileIrradiance
// (the default) reads the tile irradiance the seabed caustics read, WavefrontAreaRatio its
// window's depth layers and, beyond the window, the tile irradiance, as the seabed does there;
// RayDeviation keeps its factor ω from the water slopes at each sample (shafts that do not
// line up with the seabed's pattern). Flat water gives the unmodulated shafts with every model.
// Ray deviation's factor is at most 1, so a pixel gets at most E * intensity * sigma_s / sigma_t;
// an irradiance field focuses (its mean is flat water's 1), so a ray inside a bright sheet can get
// up to the field's clamp (CausticsSettings::maxIrradiance) times that.
struct GodRaySettings {
  // Off: the pass is skipped (0 ms).
  bool enabled = true;
  // Most grid-plane hits (samples) per pixel, kGodRaySampleCountRange. Cost is linear in it.
  int sampleCount = 16;
  // Distance between neighbouring planes of each family (m), kGridSpacingRange. Smaller gives finer
  // shafts near the camera but reaches less far with the same sampleCount.
  float gridSpacing = 0.75f;
  // Multiplier on the in-scattered sun light, kIntensityRange. Stands for the phase function
  // and artistic scale.
  float intensity = 1.5f;
  // Distance below the water level (m) over which samples fade in from 0 at the surface, which
  // hides the grid where the refracted rays have not focused yet, kFadeDepthRange. 0 = no fade.
  float surfaceFadeDistance = 2.0f;
  // e-folding depth (m) of the extra fade with depth below the level (the seed's simple
  // out-scattering term), kDepthFadeDistanceRange. 0 = no extra fade.
  float depthFadeDistance = 40.0f;
  // Longest march along a view ray (m), used for the sky and anything farther,
  // kMaxMarchDistanceRange.
  float maxDistance = 60.0f;
  // Quarter by default: as accurate as full and half resolution against a dense march of the
  // same light, the march's own sampling error dominating, for a sixteenth of the full march
  // (the error and cost of each: docs/measurements.md, "God-ray resolution"). Silhouettes stay
  // sharp (depth-aware upsample); the finest shafts are softer.
  GodRayResolution resolution = GodRayResolution::Quarter;
  // Shift the grid per pixel by a 4x4 ordered-dither phase that is fixed on screen and in time:
  // breaks the banding of few samples into fine static noise, without temporal flicker.
  bool dither = false;
};

}  // namespace postfx
