#pragma once
// How strongly a caustic pattern is streaked along the sun's azimuth: the gradient energy across
// the azimuth over the energy along it. A pattern of lines running toward the sun changes fast
// across them and slowly along them (> 1); an isotropic one gives 1. Traced light with the sun
// 60-85 degrees high gives 1.1-1.25 (the refraction foreshortens the waves' tilt along the
// plane of incidence a little).
#include <vector>

#include <glm/glm.hpp>

namespace ocean::validation {

// `values`: countX x countZ samples of a regular grid (row-major, x fastest) of binX x binZ m;
// `towardSun`: world direction (its horizontal part is the azimuth; x for a sun at the zenith).
// Central differences over the interior; 0 when there is no gradient along the azimuth.
double streakRatio(const std::vector<double>& values, int countX, int countZ, double binX,
                   double binZ, const glm::dvec3& towardSun);

}  // namespace ocean::validation
