#pragma once
// The path of the sunlight the water reflects upward, for the traced frame reference's reflected
// light above the water (FrameTraceDesc::reflected): flat water's mirror direction, how far the
// waves can move where a receiver's light comes from, which receivers can get any, and where a
// reflected ray meets the water again (a low sun's light mirrored into the next wave).
#include <glm/glm.hpp>

#include "seabed_reference.h"

namespace ocean::reference {

// l_r: from a receiver above flat water down toward the water point that mirrors the sun to
// it, (sun.x, -sun.y, sun.z) for the unit vector toward the sun; flat water's reflected ray
// rises along -l_r.
glm::dvec3 flatMirrorDirection(const glm::dvec3& towardSun);

// Where, per metre of rise, the light reflected by a water normal tilted by at most maxSlope
// goes sideways: the horizontal drift ray.xz / ray.y of every such reflected ray lies within
// `radius` of `centre` (sampled densely over the normals: a mirror turns the ray by twice its
// tilt). Flat water's ray drifts -sun.xz / sun.y; a low sun's reflections spread mostly along
// it, so the circle is centred on the spread, not on flat water's ray. Rays rising at less than
// kMinMirrorElevation are counted as rising at it: the reference leaves out light that reaches a
// receiver that flatly from farther away (it would widen every receiver's launch disc by tens of
// metres for the steepest slopes' share).
inline constexpr double kMinMirrorElevation = 0.1745329251994330;  // 10 degrees
struct MirrorDrift {
  glm::dvec2 centre{0.0};
  double radius = 0.0;
};
MirrorDrift mirrorDrift(const glm::dvec3& towardSun, double maxSlope);

// Whether a surface of unit normal `normal` can be hit from below by light the water reflects
// (some reflected ray within twice maxSlope, and the sun's angular radius, of flat water's
// meets it from the front). Up-facing decks and roofs cannot.
bool mayReceiveMirrorLight(const glm::dvec3& normal, const glm::dvec3& towardSun, double maxSlope,
                           double sunAngularRadius);

struct WaterCrossing {
  enum class Kind { Clear, Meets, Lost };
  Kind kind = Kind::Clear;  // Clear: rises above the crests without touching the water again
  double t = 0.0;           // Meets: distance along the ray to the crossing
};

// Where the ray from `from` (on or above the surface: world x, z and height above the level)
// along unit `dir` first goes under the surface again, before it rises above the highest crest.
// Rays climbing faster than the steepest slope never do (no sampling); others are marched with
// steps the slope bound makes safe, at least a quarter of the surface's feature size. Lost: it
// grazes on for more steps than a reference should spend (its light is left out).
WaterCrossing nextWaterCrossing(const Surface& water, const glm::dvec3& from,
                                const glm::dvec3& dir);

}  // namespace ocean::reference
