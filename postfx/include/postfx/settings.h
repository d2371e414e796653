#pragma once
// Per-frame tuning of the seabed caustics and the god rays: plain structs with defaults. Every
// float must be finite and inside its range (the k...Range constants, which validation uses),
// or dispatch() returns InvalidArgument and draws nothing. CausticsSettings is validated in
// every frame, whatever the features and model; GodRaySettings only with Feature::GodRays.
#include <postfx/range.h>

namespace postfx {

// What the seabed caustics (and the god rays) multiply the sun light by.
enum class CausticsModel {
  // omega = exp(-tau a^2), a the sine of the angle between the sun ray refracted (and
  // reflected) by the local water normal and its flat-water ray: a pattern without absolute
  // scale (flat water gives 1, waves only darken). No pre-pass; any receiver shape. The whole
  // deviation is used, not its component across the plane of incidence, which streaks the
  // pattern along the sun's azimuth.
  RayDeviation,
  // Caustic irradiance relative to flat water from the wavefront area ratio: every frame a grid
  // over the water is refracted onto depthLayers receiver depths and its triangles added up
  // (brightness = beam area / refracted area), then each depth blurred by the landing spread of
  // the slopes finer than the grid's cells and of the sun's disc (tileUnresolvedSpread,
  // Sun::angularDiameterDegrees). Needs Feature::WavefrontAreaRatio. Covers a
  // camera-centred square (windowSize); across its outer eighth and beyond it, the light fades
  // to the TileIrradiance field (same units, computed too), so there is no edge.
  WavefrontAreaRatio,
  // Caustic irradiance relative to flat water, everywhere, from a screen-independent pre-pass:
  // each cascade that can focus light within maxReceiverDepth refracts its own periodic tile
  // onto tileDepthLayers depths. A pixel multiplies one filtered lookup per such cascade, each
  // moved by the coarser cascades' refraction. Mip-filtered: far pixels get their footprint's
  // mean. Assumption: the product of per-cascade fields stands in for refracting through their
  // sum. It holds where the cascades' scales are far apart and overshoots (too contrasty, too
  // bright peaks) where two cascades focus near the receiver's depth (docs/measurements.md, "The
  // pattern alone"). Receivers should lie within maxReceiverDepth (deeper ones get its light).
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

// Where TileIrradiance looks its irradiance up. The light varies on the scale of the caustic
// network, several pixels wide at any distance (the lookup is filtered over the footprint),
// so every other pixel suffices; the four filtered fetches per lookup are most of the cost.
enum class CausticsLookupResolution {
  Full = 1,  // every pixel
  // Every other pixel in x and y into a plugin-owned GL_R32UI texture (irradiance and distance
  // as two halves, 4 bytes a texel), blended back per pixel by bilinear weight times distance
  // similarity, so no light bleeds across silhouettes; normal, shadow, albedo and absorption
  // stay per pixel.
  Half = 2,
};
inline constexpr Range<float> kTileMinModulationRange{0.0f, 1e3f};

struct CausticsSettings {
  // Off: the pass is skipped (0 ms) and, with testing::RawCausticOutput, the raw texture reads 0.
  bool enabled = true;

  // RayDeviation only: the tightening tau of omega = exp(-tau a^2), unitless, kTauRange. Larger
  // gives thinner, sharper lines; 0 gives omega = 1 (uniform light). TileIrradiance (the
  // default) and WavefrontAreaRatio ignore it, bit for bit, seabed and god rays alike.
  float tau = 800.0f;

  // RayDeviation only, like tau (ignored bit for bit by the other models): share of the
  // reflected ray's omega blended into the refracted one's, kUnitRange; 0 = refraction only.
  float reflectionWeight = 0.25f;

  // Multiplier on Sun::irradiance for the caustic light added, unitless, kIntensityRange. The
  // light is a copy of the direct underwater sun without 1/pi and surface Fresnel, so
  // (1 - F) / pi replaces a Lambertian direct sun (docs/integration.md, "Composition").
  float intensity = 1.0f;

  // Depth below the water level (m) over which caustics ramp in from 0 at the surface (where
  // the refracted rays have not focused yet) to full strength, kFadeDepthRange; 0 = no fade.
  float surfaceFadeDepth = 1.0f;

  // With Feature::TriplanarWalls: exponent k of the tri-planar weights |n|^k from the G-buffer
  // normal, kTriplanarSharpnessRange. Higher: each surface uses the one projection it faces
  // most (fewer fetches on a GPU). Validated always, unused without the feature.
  float triplanarSharpness = 8.0f;

  // Added to the water-texture mip level chosen from each pixel's footprint, in mip levels,
  // kLodBiasRange. Positive blurs sooner with distance, which hides tile repetition.
  float lodBias = 0.0f;

  // Cascades whose first-order irradiance modulation at a receiver's depth
  // (WaterSurface::rmsLaplacian) is below this are not sampled there; between it and twice it
  // they fade in. kUnitRange; 0 samples every cascade. Also applies to the god rays.
  float minCascadeContrast = 0.1f;

  // The light field of the seabed caustics and of the god rays (see GodRaySettings). With
  // TileIrradiance and WavefrontAreaRatio the field's pre-pass runs whenever either draws (god
  // rays alone included) and is left out when neither does.
  CausticsModel model = CausticsModel::TileIrradiance;

  // --- TileIrradiance (and WavefrontAreaRatio beyond its window); validated always ---
  // Irradiance texels per side of each cascade's tile, a power of two in kTileResolutionRange;
  // should follow the water (waves a few texels long need more, finer makes the pattern too
  // sharp: docs/measurements.md). GPU memory per cascade with irradiance: tileResolution^2 *
  // tileDepthLayers * (8/3 + 4, + 8 with the spread) bytes: 0.96 MB at the defaults.
  int tileResolution = 128;
  // Refracted water points per irradiance texel and side, 1 or 2; each carries the mean slope
  // and height of its cell of the water texture. 2 quadruples the pre-pass for a smoother
  // density where light converges.
  int tilePointsPerTexel = 1;
  // Depth layers per cascade, 4 or 8 (layer k at maxReceiverDepth * ((k + 1) / layers)^1.5):
  // one or two filtered fetches per cascade and pixel.
  int tileDepthLayers = 4;
  // Cascades whose first-order irradiance modulation at maxReceiverDepth
  // (WaterSurface::rmsLaplacian; 0 = unknown keeps the cascade) is below this get no
  // irradiance of their own and only move the finer cascades' light, kTileMinModulationRange.
  float tileMinModulation = 0.25f;
  // Soften each cascade's field, per depth layer, by the landing spread of the slopes its points
  // do not resolve (measured from the water texture every frame), as such ripples diffuse the
  // light. Off: the points' pattern alone, sharper than the real light, with rings. Also the
  // WavefrontAreaRatio window's, for the slopes inside its grid's cells: right for a sea of
  // many ripples (an FFT ocean), too soft for a few coherent ones its grid does not resolve
  // (docs/measurements.md, "The wavefront area ratio's landing spread").
  bool tileUnresolvedSpread = true;
  // Resolution of the lookups (CausticsLookupResolution). Half: a quarter of the lookups plus a
  // 4-tap upsample, 4 bytes per reduced texel (0.9 MB at 1280x720).
  CausticsLookupResolution tileLookupResolution = CausticsLookupResolution::Half;

  // --- WavefrontAreaRatio only; validated always ---
  // Surface grid vertices and irradiance texels per side, kGridResolutionRange; cost grows with
  // its square, ripples finer than windowSize * 1.25 / gridResolution are smoothed away (their
  // light is spread instead, tileUnresolvedSpread). GPU memory at 4 depthLayers: 1.1 / 4.4 /
  // 17.4 / 69.4 MiB at 128 / 256 / 512 / 1024 (about (depthLayers * 28/3 + 32) bytes per grid
  // point; 16/3 instead of 28/3 with neither spread nor sun disc), plus the tile field's.
  int gridResolution = 256;
  // Side of the square receiver window around the camera (m), kWindowSizeRange; snapped to
  // whole texels in world space so the pattern does not swim when the camera moves.
  float windowSize = 32.0f;
  // Receiver depths, kDepthLayersRange: layer k at maxReceiverDepth * ((k + 1) / depthLayers)^2
  // below the level (denser near the surface, where the pattern changes fastest). A pixel
  // interpolates linearly between the layers around it (1, flat water, at the surface).
  int depthLayers = 4;
  // Deepest receiver layer (m) of WavefrontAreaRatio and TileIrradiance,
  // kMaxReceiverDepthRange. Deeper receivers get that layer's light.
  float maxReceiverDepth = 16.0f;
  // Irradiance clamp relative to flat water, kMaxIrradianceRange: folds focus to infinite
  // irradiance. WavefrontAreaRatio clamps its window to it (the flux removed:
  // FrameStats::clampedFluxFraction); TileIrradiance each cascade's field to min(it, 1024),
  // and their product to 1024 (half-float targets and lookups stay finite).
  float maxIrradiance = 32.0f;
};

}  // namespace postfx

namespace postfx {

// Resolution the god-ray march runs at. Below full, each texel of a plugin-owned GL_RG32UI
// texture (light and distance as four halves, 8 bytes) marches the ray of the first pixel of
// its block, and a depth-aware (bilateral) upsample adds the result into the target; shafts
// are soft, so little is lost for 1/4 or 1/16 of the march (docs/measurements.md).
enum class GodRayResolution {
  Full = 1,
  Half = 2,     // 1/4 of the march
  Quarter = 4,  // 1/16 of the march; the finest shafts softer (the default)
};

inline constexpr Range<int> kGodRaySampleCountRange{4, 64};
inline constexpr Range<float> kGridSpacingRange{0.01f, 1e3f};       // m
inline constexpr Range<float> kDepthFadeDistanceRange{0.0f, 1e5f};  // m
inline constexpr Range<float> kMaxMarchDistanceRange{0.1f, 1e5f};   // m

// Single scattering of the sun along each view ray under the water (Feature::GodRays):
//   L = E_sun * intensity * sigma_s / sigma_t * (1 - exp(-sigma_t * D)) * gamma,
// sigma_* from WaterSurface, gamma the average of the light factor at the samples where the
// ray crosses a world-snapped grid of planes (weighted by segment length and view-path
// transmittance). The factor is the caustics model's field at the sample's depth
// (CausticsSettings::model): TileIrradiance and WavefrontAreaRatio read the field the seabed
// reads, so shafts line up with its pattern; RayDeviation its omega from the water slopes (at
// most 1, so L <= E * intensity * sigma_s / sigma_t). Flat water gives the unmodulated shafts
// in every model; an irradiance field's mean is flat water's 1, but a ray inside a bright sheet
// can reach the field's clamp times that.
struct GodRaySettings {
  // Off: the pass is skipped (0 ms).
  bool enabled = true;
  // Most grid-plane hits (samples) per pixel, kGodRaySampleCountRange. Cost is linear in it.
  int sampleCount = 16;
  // Distance between neighbouring planes of each family (m), kGridSpacingRange. Smaller: finer
  // shafts near the camera, but the same sampleCount reaches less far.
  float gridSpacing = 0.75f;
  // Multiplier on the in-scattered sun light, kIntensityRange; 0 skips the pass. Stands for
  // the phase function (1 / (4 pi) is isotropic scattering) and artistic scale.
  float intensity = 1.5f;
  // Distance below the water level (m) over which samples fade in from 0 at the surface,
  // hiding the grid where the refracted rays have not focused yet, kFadeDepthRange; 0 = no fade.
  float surfaceFadeDistance = 2.0f;
  // e-folding depth (m) of an extra fade with depth below the level (a simple out-scattering
  // term), kDepthFadeDistanceRange; 0 = no extra fade.
  float depthFadeDistance = 40.0f;
  // Longest march along a view ray (m), for the sky and anything farther, kMaxMarchDistanceRange.
  float maxDistance = 60.0f;
  // March resolution (GodRayResolution). Quarter: against a dense march of the same light the
  // march's own sampling error dominates at every resolution, so it costs little accuracy;
  // silhouettes stay sharp (depth-aware upsample), the finest shafts are softer.
  GodRayResolution resolution = GodRayResolution::Quarter;
  // Shift the grid per pixel by a 4x4 ordered-dither phase, fixed on screen and in time: breaks
  // the banding of few samples into fine static noise, without temporal flicker.
  bool dither = false;
};

}  // namespace postfx
