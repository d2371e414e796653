#pragma once
// Exact CPU ray tracing (double precision) of the object caustics of a point or spot light (a
// light at a finite distance, postfx::LocalLight's model): rays from the light's position over
// the solid angle the caster subtends, refracted through a glass sphere (exact unpolarised
// Fresnel at both surfaces, Beer-Lambert along the chord), dimmed by the spot's cone and by the
// medium's Beer-Lambert absorption along both legs (light to caster, caster to receiver), and
// binned as irradiance on a receiver plane of any orientation (a floor, a wall, a plane facing
// the light). The inverse-square law is not applied per ray: it comes out of binning the flux of
// a fixed solid angle onto the plane's area. Deterministic: stratified rays (equal solid angle
// per stratum) with a fixed seed, rows split over 2 threads.
#include <cstddef>
#include <glm/glm.hpp>
#include <vector>

#include "object_caustics_reference.h"

namespace ocean::reference {

// A point light, or a spot light when `spot` is set (postfx::LocalLight's fields, in double).
struct LocalLightSource {
  glm::dvec3 position{0.0};
  // Radiant intensity per channel: the irradiance at 1 m on the axis, on a surface facing the
  // light, through a clear medium (postfx::LocalLight::intensity's unit).
  glm::dvec3 intensity{1.0};
  bool spot = false;
  glm::dvec3 direction{0.0, -1.0, 0.0};  // spot axis (normalised here)
  double coneAngleDegrees = 60.0;        // spot: full apex angle
  double coneSoftness = 0.2;             // spot: share of the half-angle faded at the edge
};

// The spot's cone factor for a ray leaving the light along `dir` (unit): 1 inside the cone's
// core, 0 outside the half-angle h, and between them 1 - smoothstep(h (1 - softness), h, angle)
// in the angle from the axis (postfx::LocalLight::coneSoftness). 1 for a point light.
double coneFactor(const LocalLightSource& light, const glm::dvec3& dir);

// A square grid of size x size bins on a plane: the plane through `origin` spanned by `axisU`
// and `axisV` (perpendicular, the grid's full sides), bin (i, j) covering
// origin + [i, i + 1) / size axisU + [j, j + 1) / size axisV; row j = 0 first.
struct ReceiverBins {
  glm::dvec3 origin{0.0}, axisU{1.0, 0.0, 0.0}, axisV{0.0, 0.0, 1.0};
  int size = 1;
};
// Bins on the floor y = planeY: a square of side `side` (m) centred below `centre`.
ReceiverBins floorBins(const glm::dvec3& centre, double planeY, double side, int size);
// Bins on the plane facing the light at `distance` (m) along unit `axis`, side `side` (m).
ReceiverBins facingBins(const glm::dvec3& light, const glm::dvec3& axis, double distance,
                        double side, int size);
// The world position of a continuous bin coordinate (bin units, (0.5, 0.5) = first bin's centre).
glm::dvec3 binPoint(const ReceiverBins& bins, const glm::dvec2& bin);
// Area of one bin (m^2).
double binArea(const ReceiverBins& bins);
// The row-major index of the bin that `point` (on the bins' plane) falls in, or -1 outside them.
std::ptrdiff_t binIndex(const ReceiverBins& bins, const glm::dvec3& point);

// One ray through the glass sphere (SphereCaster's ior, absorption, transmission, tint and
// thinWalled; roughness and dispersion are not traced here). `origin` outside the sphere, or
// inside it (then the ray only leaves: one refraction, one Fresnel, absorption to the exit).
struct SphereRay {
  bool hit = false;               // the ray met the sphere
  bool leaves = false;            // refracted out (false: total internal reflection)
  glm::dvec3 entry{0.0};          // where it met the sphere (origin itself when inside)
  glm::dvec3 exit{0.0};           // where it leaves
  glm::dvec3 direction{0.0};      // unit, after leaving
  glm::dvec3 transmittance{0.0};  // Fresnel x absorption x transmission x tint
};
SphereRay traceThroughSphere(const SphereCaster& sphere, const glm::dvec3& origin,
                             const glm::dvec3& dir);

struct LocalCausticReference {
  int size = 0;
  std::vector<glm::dvec3> irradiance;  // per bin, in the light's intensity units / m^2
  glm::dvec3 fluxInBins{0.0};          // landed inside the bins (intensity units x sr)
  glm::dvec3 fluxOutside{0.0};         // landed on the plane outside the bins
  glm::dvec3 fluxLeaving{0.0};         // left the caster, wherever it goes (before leg 2)
  glm::dvec3 fluxEmitted{0.0};         // the light's flux into the sampled solid angle (cone
                                       // and leg-1 absorption not applied)
  double solidAngle = 0.0;             // sr the rays were spread over
};

// The caustic of `sphere` lit by `light` on the plane of `bins`: only the light that went through
// the sphere (what the plugin adds inside the sphere's shadow). `mediumAbsorption`: Beer-Lambert
// coefficients per metre of the medium the light, sphere and receiver share (0 in air; water's
// under water, with the sphere's ior relative to water). raysPerSide^2 rays over the cap of
// directions the sphere subtends (all directions when the light is inside it). `seed` picks the
// jitter: two seeds give independent estimates.
LocalCausticReference traceSphereFromLight(const SphereCaster& sphere,
                                           const LocalLightSource& light, const ReceiverBins& bins,
                                           const glm::dvec3& mediumAbsorption, int raysPerSide,
                                           unsigned seed = 0);

// The same for the metal ring's one specular bounce (Schlick reflectance), for a light above the
// ring's top (reflectOffRing's rays come down into it): rays over the cap of the ring's bounding
// sphere; nothing (an empty result) for a light at or below the top.
LocalCausticReference traceRingFromLight(const RingCaster& ring, const LocalLightSource& light,
                                         const ReceiverBins& bins,
                                         const glm::dvec3& mediumAbsorption, int raysPerSide,
                                         unsigned seed = 0);

// The light's direct irradiance on the plane of `bins` with nothing in the way (the same
// sampling and binning, rays over the cone that holds the bins' corners): the ground truth of
// the inverse-square law, the cone's edge and the medium's absorption.
LocalCausticReference traceDirectLight(const LocalLightSource& light, const ReceiverBins& bins,
                                       const glm::dvec3& mediumAbsorption, int raysPerSide,
                                       unsigned seed = 0);

// Where a ray leaving the light toward the sphere's centre at `angle` (radians) off that line
// crosses the line again after the sphere: its distance from the sphere's centre (m), or a
// negative value when it does not (misses, or diverges). The thick-lens image of the light
// along its axis, for one zone of the aperture.
double axisCrossingFromCentre(const SphereCaster& sphere, const glm::dvec3& light, double angle);

}  // namespace ocean::reference
