#pragma once
// The frame's geometry every pass shares, in double: the tile fraction of a world position, the
// refracted sun, the sun's plane of incidence, the camera's rotation, and what validation learnt
// of the water texture.
#include <glm/glm.hpp>

namespace postfx::detail {

// Size and mip count of the water texture, from validation.
struct WaterTextureInfo {
  int width = 1;
  int height = 1;
};

// x - floor(x / period) * period, divided by period: the fraction of a tile, in [0, 1).
double tileFraction(double metres, double period);

// The sun ray refracted through flat water (pointing down), eta = 1 / IOR.
glm::dvec3 refractedSunDown(const glm::dvec3& towardSun, double ior);

// Unit vector perpendicular to the plane of incidence (vertical plane containing the sun); the
// ray deviation's [1] reference vector for both unperturbed rays. World x for a sun at the zenith.
glm::dvec3 incidencePlaneNormal(const glm::dvec3& towardSun);

// World-to-view rotation part of the camera's view matrix, transposed: view -> world.
glm::dmat3 viewToWorldRotation(const glm::mat4& view);

}  // namespace postfx::detail
