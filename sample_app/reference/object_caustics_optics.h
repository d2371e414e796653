#pragma once
// Exact optics at a smooth dielectric surface, shared by the object-caustics references (sun and
// local lights): unpolarised Fresnel reflectance and Snell refraction, in double.
#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>
#include <optional>

namespace ocean::reference {

// Unpolarised Fresnel reflectance for a ray meeting the surface at cos(incidence) `cosI`, going
// from a medium of index n1 into n2, eta = n2 / n1. 1 under total internal reflection.
inline double fresnel(double cosI, double eta) {
  cosI = std::clamp(cosI, 0.0, 1.0);
  const double sinT2 = (1.0 - cosI * cosI) / (eta * eta);
  if (sinT2 >= 1.0) return 1.0;
  const double cosT = std::sqrt(1.0 - sinT2);
  const double rs = (cosI - eta * cosT) / (cosI + eta * cosT);
  const double rp = (eta * cosI - cosT) / (eta * cosI + cosT);
  return 0.5 * (rs * rs + rp * rp);
}

// Snell refraction of unit `i` at unit normal `n` (facing against i), eta = n1 / n2; nothing
// under total internal reflection.
inline std::optional<glm::dvec3> refractRay(const glm::dvec3& i, const glm::dvec3& n, double eta) {
  const double c = -glm::dot(n, i);
  const double k = 1.0 - eta * eta * (1.0 - c * c);
  if (k < 0.0) return std::nullopt;
  return eta * i + (eta * c - std::sqrt(k)) * n;
}

}  // namespace ocean::reference
