#pragma once
// Reflected caustics above the water (Feature::ReflectedCaustics): the sunlight the waves mirror
// upward, the moving bright network on a hull, the underside of a pier, a harbour wall or a cliff.
// Per view (like WavefrontAreaRatio's window, it follows the view's camera, centred a quarter of
// its side ahead of it along the view), a grid over the water there reflects the sun (law of
// reflection through the waves' own normals and heights, Fresnel reflectance per grid point, less
// the light the next crest catches) onto heightLayers horizontal layers above the level, folds
// summed as the wavefront area ratio sums them under the water; each layer holds the light
// crossing it (I) and that light times its rays' drift (D). A pixel above the level then receives
//     albedo * E_sun * intensity * R(theta_sun) * sun.y * max(-n.y I - n.x D.x - n.z D.z, 0),
// what the rays arriving at it deliver to its normal n: over a flat sea, I * max(n . l_r, 0),
// l_r the flat-water reflected sun reversed (from the receiver down toward the water), R the
// unpolarised Fresnel reflectance of flat water at the sun's incidence and I the field's
// irradiance relative to flat water's mirror light (1 over a flat sea). Between layers the
// field is looked up along the mean ray arriving at the pixel.
// Surfaces facing up, under the water, on the sky or facing away from the water get none.
// Visibility: with Feature::ShadowMask, the host's sun shadow map at every water point the grid
// mirrors, so water in the shade of a pier or hull mirrors nothing onto its underside (beyond
// the window, at the receiver's flat-water mirror point); without it, all the water mirrors the
// sun. The path from the water up to the receiver is taken as clear (the receiver faces the
// water and is the first surface the mirror ray meets in the usual hull, pier and wall; an
// object between them is not seen).
// Composition: the light is ADDED into FrameDesc::target like the underwater caustics.
// docs/integration.md, "Reflected caustics".
#include <postfx/range.h>
#include <postfx/settings.h>

namespace postfx {

inline constexpr Range<float> kReflectedHeightRange{0.01f, 1e4f};  // m above the level
inline constexpr Range<int> kReflectedLayersRange{1, 8};

struct ReflectedCausticsSettings {
  // Off: the pass is skipped (0 ms), nothing is allocated.
  bool enabled = true;
  // Multiplier on the reflected light, kIntensityRange; 1 is physical, 0 skips the pass.
  float intensity = 1.0f;
  // true: the whole mirror light, its flat-water mean R * E included. false: only the waves'
  // modulation of it, R * E * (I - 1) (it darkens too), for a host whose lighting already holds
  // the sun mirrored by a flat sea (a planar-reflection light, a baked water bounce): adding
  // the mean again would count the mirrored sun twice.
  bool includeMirrorMean = true;
  // Side of the square window the pattern is computed over (m), kWindowSizeRange: centred a
  // quarter of it ahead of the camera along the view (most receivers stand across the water
  // from it), snapped to whole texels in world space. Beyond it, across the outer eighth, the
  // pattern fades to the flat mean (the mirror light stays).
  float windowSize = 24.0f;
  // Water grid cells and irradiance texels per side of the window, kGridResolutionRange. A
  // mirror deviates light by twice the slope (refraction by a quarter of it), so reflected lines
  // are sharp and fine: at the default 24 m / 512 a cell is 5.9 cm, ripples shorter than ~4
  // cells are carried as a blur of their slopes instead (the landing spread). Cost grows with
  // its square.
  int gridResolution = 512;
  // Horizontal receiver layers above the level, kReflectedLayersRange: layer k at
  // maxHeight * ((k + 1) / heightLayers)^2 (the pattern changes fastest near the water, where
  // short waves focus). A receiver between two layers interpolates them along its mean ray: the
  // pattern between layers is approximated, so more layers (or one at a receiver's height) follow
  // it better (docs/measurements.md, "Reflected caustics").
  int heightLayers = 6;
  // Height of the highest layer above the level (m), kReflectedHeightRange. Above it the
  // pattern fades to its mean over a further half of it: up there the waves' deviations have
  // spread each point's light over more than the pattern's scale.
  float maxHeight = 6.0f;
  // Irradiance clamp relative to flat water's mirror light, kMaxIrradianceRange (folds focus to
  // infinity).
  float maxIrradiance = 32.0f;
};

}  // namespace postfx
