#pragma once
// The sun as the sample's frame sees it: dimmed and reddened by the atmosphere above the water,
// then through the mean surface (1 - Fresnel) below it. One place for both, because under the
// water the sample does not light with the sun itself: the plugin's caustic light *is* the
// underwater sun (shaders/sample/lighting.frag), so the plugin must be given exactly the light
// the sample's own sun would have had.
#include <glm/glm.hpp>

#include "camera.h"

namespace ocean {

// Irradiance (linear RGB, the sample's HDR units) on a surface facing the sun just above the
// water: Sun::irradiance through the atmosphere's air mass. 0 with the sun below the horizon.
glm::vec3 sunIrradianceAboveWater(const Sun& sun);

// Share of the sun's beam the flat water lets through, 1 - F(theta_sun) for water of index
// `ior` (Fresnel, unpolarised); 0 with the sun at or below the horizon.
float sunTransmission(const Sun& sun, double ior);

// The refracted beam just below the flat surface, per unit area across it: what the plugin is
// given as Sun::irradiance, so that caustics.intensity = 1/pi turns its caustic copy into the
// Lambertian direct sun (docs/integration.md, "Composition in your frame").
glm::vec3 sunIrradianceBelowSurface(const Sun& sun, double ior);

}  // namespace ocean
