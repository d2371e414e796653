#pragma once
// Reflected caustics above the water (Feature::ReflectedCaustics): the sunlight the waves mirror
// upward, the moving bright network on a hull, the underside of a pier, a harbour wall or a cliff.
// Per view, a grid over the water (a window centred a quarter of its side ahead of the camera,
// and around it a grid four times as wide and as coarse) reflects the sun: law of reflection
// through the waves' own normals and heights, Fresnel reflectance per grid point, less the
// light the next crest catches. Where the rays go (ReflectedCausticsSettings::landing):
// - ViewDepth (default): each ray is followed through the view's depth to the receiver it
//   meets, and each grid triangle adds its flux over the area it landed on (folds summed), then
//   blurred by the sun's disc and the slopes finer than the grid. A receiver gets exactly what
//   lands on it, at any height and orientation, shaded by what the view shows between it and
//   the water (a pillar in front of a wall); what the view does not show neither receives nor
//   shades.
// - HeightLayers: the rays land on heightLayers horizontal layers above the level holding the
//   light crossing each (I) and that light times its rays' drift (D); a pixel receives
//   sun.y * max(-n.y I - n.x D.x - n.z D.z, 0), interpolated between layers along the mean ray
//   arriving at it. Independent of the view's depth, approximate between layers.
// Either way a pixel above the level receives albedo * E_sun * intensity * R(theta_sun) * L,
// L its light relative to flat water's mirror light on a face turned to the mirrored sun: over a
// flat sea, max(n . l_r, 0), l_r the flat-water reflected sun reversed (from the receiver down
// toward the water), R the unpolarised Fresnel reflectance of flat water at the sun's incidence.
// Beyond the grids' reach the light is that flat mean.
// Under the water, on the sky and on faces no ray reaches (facing up, or away from the water):
// none.
// Visibility: with Feature::ShadowMask, the host's sun shadow map at every water point the grid
// mirrors, so water in the shade of a pier or hull mirrors nothing onto its underside (beyond
// the grids, at the receiver's flat-water mirror point); without it, all the water mirrors the
// sun. Between the water and the receiver: ViewDepth, what the view's depth shows; HeightLayers,
// clear (the receiver faces the water and is the first surface the mirror ray meets in the
// usual hull, pier and wall).
// Composition: the light is ADDED into FrameDesc::target like the underwater caustics.
// docs/integration.md, "Reflected caustics".
#include <postfx/range.h>
#include <postfx/settings.h>

namespace postfx {

inline constexpr Range<float> kReflectedHeightRange{0.01f, 1e4f};  // m above the level
inline constexpr Range<int> kReflectedLayersRange{1, 8};
// Water grid cells per side (ReflectedCausticsSettings::gridResolution): finer than the
// refracted window's at the top, since a mirror's lines are four times as sharp.
inline constexpr Range<int> kReflectedGridRange{64, 2048};

// Where the mirrored rays are followed to (both: the same water grid, the same light).
enum class ReflectedLanding {
  // To the receivers the view's depth shows: every grid point's ray is marched through the
  // G-buffer depth to the surface it meets and the grid's triangles carry their flux there.
  // Exact at any receiver height and orientation, per view (its cost and memory scale with the
  // grid and the view); a receiver the view does not show cannot be lit and an occluder it does
  // not show does not shade.
  ViewDepth,
  // Onto heightLayers horizontal layers, interpolated between them at each receiver: the field
  // does not depend on the view's depth, but the pattern between layers is approximated.
  HeightLayers,
};

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
  // Where the mirrored rays are followed to; heightLayers and the layer law below apply to
  // HeightLayers only (maxHeight to both: no receiver above 1.5 maxHeight gets the pattern).
  ReflectedLanding landing = ReflectedLanding::ViewDepth;
  // Side of the square window the pattern is computed over (m), kWindowSizeRange: centred a
  // quarter of it ahead of the camera along the view (most receivers stand across the water
  // from it), snapped to whole texels in world space. With ViewDepth, a grid four times as wide
  // and as coarse around it lights the far and high receivers. Beyond the outermost grid, across
  // its outer eighth, the pattern fades to the flat mean (the mirror light stays).
  // Reach at the default 24 m, ahead of the camera along the view: HeightLayers to about 18 m
  // (the window, 6 m ahead +- 12 m; a wall 20 m away gets only the flat mean), ViewDepth to
  // about 54 m (its outer grid, 96 m wide); to the sides half the width, behind the camera
  // 6 m (HeightLayers) or 42 m. Widen the window for far receivers: its cells grow with it.
  float windowSize = 24.0f;
  // Water grid cells per side of the window (and of the outer grid), kReflectedGridRange. A
  // mirror deviates light by twice the slope (refraction by a quarter of it), so reflected lines
  // are sharp and fine: at the default 24 m / 512 a cell is 4.7 cm, ripples shorter than ~4
  // cells are carried as a blur of their slopes instead (the landing spread). Cost grows with
  // its square. ViewDepth: (n + 1)^2 * 32 bytes of rays (8.4 MB at 512, 134 MB at 2048) plus 16
  // bytes per G-buffer pixel; beyond the ripples' focus (a pier's underside) a pixel's light is
  // the sum of the rays landing on it, so a finer grid also means less noise there
  // (docs/measurements.md, "Reflected caustics"). HeightLayers: the layers' texels too.
  int gridResolution = 512;
  // HeightLayers only: horizontal receiver layers above the level, kReflectedLayersRange: layer k
  // at maxHeight * ((k + 1) / heightLayers)^2 (the pattern changes fastest near the water, where
  // short waves focus). A receiver between two layers interpolates them along its mean ray: the
  // pattern between layers is approximated, so more layers (or one at a receiver's height) follow
  // it better (docs/measurements.md, "Reflected caustics").
  int heightLayers = 6;
  // Height of the highest receiver the pattern is drawn on (m above the level; the highest
  // layer's with HeightLayers), kReflectedHeightRange. Above it the pattern fades to its mean
  // over a further half of it (ViewDepth follows the rays that far): up there the waves'
  // deviations have spread each point's light over more than the pattern's scale.
  float maxHeight = 6.0f;
  // Irradiance clamp relative to flat water's mirror light, kMaxIrradianceRange (folds focus to
  // infinity).
  float maxIrradiance = 32.0f;
};

}  // namespace postfx
