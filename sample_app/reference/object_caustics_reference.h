#pragma once
// Exact CPU ray tracing (double precision) of the object caustics the plugin approximates: a
// glass sphere (refraction in and out, exact unpolarised Fresnel at both surfaces, Beer-Lambert
// inside) and a reflective ring (one specular bounce, Schlick F0), over the plane y = planeY,
// binned into the plugin's caustic-map texel grid. Deterministic: stratified rays with a fixed
// seed, rows split over 2 threads.
#include <glm/glm.hpp>
#include <optional>
#include <vector>

#include <postfx/postfx.h>

namespace ocean::reference {

struct SphereCaster {
  glm::dvec3 centre{0.0};
  double radius = 1.0;
  double ior = 1.5;  // relative to the outer medium
  glm::dvec3 absorption{0.0};
  // postfx::CasterMaterial's glass fields, traced as its header states them: the transmission
  // weight and the tint once per ray; thin-walled = the ray keeps its direction and loses both
  // Fresnel reflections, no absorption; roughness = the outgoing ray deflected by a Gaussian of
  // standard deviation roughness^2 radians on each axis across it; dispersion = each channel
  // traced alone with IOR ior + (c - 1) * (ior - 1) * 0.025 * dispersion (R, G, B).
  double transmission = 1.0;
  glm::dvec3 tint{1.0};
  bool thinWalled = false;
  double roughness = 0.0;
  double dispersion = 0.0;
};

struct RingCaster {
  glm::dvec3 base{0.0};  // centre of the ring's bottom
  double inner = 1.0, outer = 1.05, height = 0.5;
  glm::dvec3 f0{1.0};  // Schlick reflectance at normal incidence
};

struct CausticReference {
  int size = 0;
  std::vector<glm::dvec3> irradiance;  // per map texel, relative to the sun's (as the GPU map)
  glm::dvec3 fluxInMap{0.0};           // landed inside the map (sun irradiance 1, m^2)
  glm::dvec3 fluxOutside{0.0};         // landed on the plane outside the map
  double interceptedArea = 0.0;        // sun-perpendicular area of rays that hit the caster
};

// `map`: the plugin's map placement (from postfx::objectCausticMap), or any other square grid of
// bins perpendicular to the light given the same way; raysPerSide^2 rays over a sun-perpendicular
// square around the caster. `seed` picks the jitter: two seeds give independent estimates, whose
// difference measures the reference's own noise.
CausticReference traceSphereReference(const SphereCaster& sphere, const glm::dvec3& towardSun,
                                      double planeY, const postfx::ObjectCausticMap& map,
                                      int raysPerSide, unsigned seed = 0);
CausticReference traceRingReference(const RingCaster& ring, const glm::dvec3& towardSun,
                                    double planeY, const postfx::ObjectCausticMap& map,
                                    int raysPerSide);

// One specular bounce off the ring for a ray coming down from above its top (`dir` unit, with
// dir.y < 0): where it reflects, its reflected direction (unit) and the Schlick reflectance.
// Nothing when the ray misses the ring.
struct RingReflection {
  glm::dvec3 point, direction, reflectance;
};
std::optional<RingReflection> reflectOffRing(const RingCaster& ring, const glm::dvec3& origin,
                                             const glm::dvec3& dir);

// The glass sphere over a plane that the accuracy test and the report measure: R = 1 m, IOR 1.5,
// tinted (absorption 0.02, 0.1, 0.3 per m), its bottom 0.4 m above the plane y = 0, the sun 25
// degrees from the zenith: the plane lies just beyond the paraxial focus (1.5 R from the
// centre), where the spherical aberration spreads the rim rays around the axial peak.
struct SphereOverPlane {
  SphereCaster sphere;
  glm::dvec3 towardSun{0.0, 1.0, 0.0};  // unit
  double planeY = 0.0;
};
SphereOverPlane glassSphereOverPlane();

// Separable Gaussian blur (sigma in texels) of a size x size map, for comparing the reference
// with the GPU's splatted map at the same resolution.
std::vector<glm::dvec3> gaussianBlur(const std::vector<glm::dvec3>& map, int size, double sigma);

}  // namespace ocean::reference
