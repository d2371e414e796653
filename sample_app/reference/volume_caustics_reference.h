#pragma once
// CPU reference of the volume caustics (Feature::VolumeCaustics): the light a glass sphere
// focuses, in-scattered toward a pinhole camera by the water it crosses, in double precision.
// Rays on a fine jittered grid across the refracted sun are traced exactly through the sphere
// (Snell and unpolarised Fresnel at both surfaces, Beer-Lambert in the glass) to a floor plane;
// each ray's way through the water is then marched in steps of half a pixel's footprint, and
// every step adds sigma_s * phase * P * T_light * rho * T_view * ds / (Omega_pixel * t^2) to the
// pixel it lies in (the radiance of a thin beam averaged over the pixel), where the pixel sees
// nothing nearer. The light model is the god rays' (postfx/settings.h, GodRaySettings): P the
// sun's irradiance times the ray's cell area, extinguished (sigma_t) along the refracted sun from
// the surface to the sphere, T_light the extinction from where the ray leaves the sphere,
// T_view the view ray's, rho the surface and depth fades. Deterministic (fixed seed), two
// threads, progress on stderr.
#include <vector>

#include <glm/glm.hpp>

#include "object_caustics_reference.h"

namespace ocean::reference {

struct VolumeCausticMedium {
  double waterLevel = 0.0;                                         // world y
  double waterIor = 1.333;                                         // relative to air
  glm::dvec3 towardSun{0.0, 1.0, 0.0};                             // unit, above the water
  glm::dvec3 sunIrradiance{1.0};                                   // Sun::irradiance
  glm::dvec3 sigmaS{0.02}, sigmaT{0.1};                            // 1/m
  double phase = 1.0 / (4.0 * 3.14159265358979323846);             // GodRaySettings::intensity
  double surfaceFade = 2.0, depthFade = 40.0, maxDistance = 60.0;  // GodRaySettings, m
};

struct VolumeCausticCamera {
  int width = 0, height = 0;
  glm::dvec3 position{0.0};                           // world
  glm::dmat3 viewToWorld{1.0};                        // rotation (view looks down -z)
  double p00 = 1.0, p11 = 1.0, p20 = 0.0, p21 = 0.0;  // the projection's terms
  // Per pixel (GL order, row 0 at the bottom): the distance to what it sees (m; a huge value
  // for nothing).
  std::vector<double> distance;
};

// `sphere.ior` relative to the water; the floor is y = planeY (world). Linear RGB per pixel.
std::vector<glm::dvec3> renderVolumeCausticReference(const SphereCaster& sphere, double planeY,
                                                     const VolumeCausticMedium& medium,
                                                     const VolumeCausticCamera& camera,
                                                     int raysPerSide, unsigned seed = 0,
                                                     bool progress = true);

}  // namespace ocean::reference
