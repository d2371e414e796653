#pragma once
// Local lights for Feature::ObjectCaustics: point and spot lights whose light the
// glass and metal casters (postfx/casters.h) focus, alongside the sun or instead of it
// (ObjectCausticsFrame::lights, ::lightCount, ::sunCaustics).
//
// Units. A light's `intensity` is a radiant intensity in the host's HDR irradiance units x m^2:
// the irradiance (the same units as Sun::irradiance) it gives at 1 m on its axis, on a surface
// facing it, through clear air. At distance d the unobstructed irradiance is intensity / d^2
// times the cone falloff (spot), times exp(-WaterSurface::absorption * path in water) when the
// path runs under the water level. The caustic added is that light after the caster has
// refracted or reflected it: Fresnel at each surface, the material's transmission, tint and
// absorption, focused or spread where the rays land.
//
// What the host does around the pass, per light (as for the sun, postfx/casters.h):
//   * It lights its scene with the light's DIRECT light itself, and keeps the casters in that
//     light's shadow map as opaque occluders, so its lighting already removes the light a caster
//     blocks. The plugin adds back the light that passes through (or is reflected by) the
//     caster, focused.
//   * It hands, per light, a receiver depth map rendered from the light WITHOUT the casters
//     (LocalLight::receivers): the surfaces the refracted and reflected rays land on.
//
// How a light is drawn. The casters within its range and cone are drawn from the light, in one
// perspective view fitted to the cone around their bounding boxes' corners (a spot's own cone
// when that is narrower), at most kMaxLightViewDegrees wide (postfx/diagnostics.h); the same
// ray grid (settings.gridSize) is traced through them as for the sun, each ray carrying the
// intensity times its cell's solid angle, the cone's falloff, Fresnel, transmission, tint and
// absorption, and splatted into a map in the light's view (settings.mapSize) that holds
// irradiance (inverse square included); then composited onto the pixels that lie on the light's
// receivers and face it. No temporal filter (settings.temporalFilter is the sun's).
//
// What is not modelled, and reported in FrameStats::lightSkip rather than drawn wrong:
//   * a light inside a caster's bounding box (LightSkip::InsideCaster);
//   * a light on the other side of the water level from the casters it reaches, e.g. a lamp
//     above the water shining down into it (LightSkip::AcrossWaterSurface): its rays would be
//     refracted at the surface, which one centre of projection cannot hold. Place such a light
//     under the water (or at its level: a light at the level counts as under water);
//   * casters spread more than kMaxLightViewDegrees around the light (LightSkip::CastersAround).
// A light under the water lights no receiver above the water level.
//
// Cost. The number of lights a frame may list is bounded by CreateDesc::maxLocalLights, fixed at
// create(). Per frame, a light that reaches no caster (range 0, intensity 0, every caster beyond
// its range or outside its cone or its receiver map) costs 0 ms and allocates nothing; each
// light that does runs the sun's passes again at the same gridSize and mapSize (its own caster
// maps, trace, splat and composite, drawn after the sun's and timed on its own:
// stats().objectLight(i)), so the cost is linear in the lights that reach a caster.
// All lights share one caustic map (mapSize^2 x 16 bytes), allocated when the first one runs.
#include <cstdint>

#include <glm/glm.hpp>

#include <postfx/frame_desc.h>
#include <postfx/range.h>

namespace postfx {

inline constexpr int kMaxLocalLightsLimit = 16;  // CreateDesc::maxLocalLights' upper bound
inline constexpr Range<double> kLightRangeRange{0.0, 1e6};       // LocalLight::range (m)
inline constexpr Range<float> kLightIntensityRange{0.0f, 1e9f};  // each channel
// Open interval: (0, 180) degrees, full apex angle. Both ends are refused.
inline constexpr Range<float> kSpotConeAngleRange{0.0f, 180.0f};
inline constexpr Range<float> kSpotConeSoftnessRange{0.0f, 1.0f};  // LocalLight::coneSoftness

enum class LocalLightType : std::uint32_t { Point, Spot };

struct LocalLight {
  LocalLightType type = LocalLightType::Spot;
  // World position (m), double: it may be ~1e6 m from the origin. Finite and within +-1e9 m
  // like every other world coordinate (postfx/frame_desc.h, Camera::position).
  glm::dvec3 position{0.0};
  // Spot: the axis it shines along. Need not be unit: normalised in double; its length must be
  // in kSunLengthRange (finite, its square too). Ignored (not validated) for a point light.
  glm::dvec3 direction{0.0, -1.0, 0.0};
  // Radiant intensity, linear RGB, in the host's HDR irradiance units x m^2: the irradiance it
  // gives at 1 m on its axis, on a surface facing it, through clear air. kLightIntensityRange.
  glm::vec3 intensity{1.0f};
  // m: casters farther than this get no light from it (0: the light makes no caustics).
  // kLightRangeRange.
  double range = 10.0;
  // Spot: full apex angle of the cone in degrees, the open interval kSpotConeAngleRange.
  float coneAngleDegrees = 60.0f;
  // Spot: share of the half-angle, from the edge inward, over which the light fades to 0
  // (smoothstep), kSpotConeSoftnessRange. 0: a hard edge.
  float coneSoftness = 0.2f;
  // Depth map from the light WITHOUT the casters (the receivers the refracted/reflected rays land
  // on), GL_TEXTURE_2D, any depth format, any perspective projection from the light that sees
  // where its light lands (a spot's own shadow map with the casters masked out is exactly that).
  // Same type and meaning as ObjectCausticsFrame::receivers for the sun. Required for every
  // light listed (validated even when the light reaches no caster).
  SunShadowMap receivers;
};

}  // namespace postfx
