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

// A ray from `o` along unit `d` through a solid sphere (centre, radius) of relative index `ior`:
// where it enters, the Fresnel transmittance there, and (unless it stops at the entry) the chord
// it runs inside, where it leaves, the transmittance there and the direction it leaves in.
// Nothing when it misses the sphere; `refracted` false when it is not refracted out.
struct SphereCrossing {
  glm::dvec3 entry{0.0}, entryNormal{0.0};
  double entryTransmittance = 0.0;
  bool refracted = false;
  double chord = 0.0;
  glm::dvec3 exit{0.0}, out{0.0};  // out: unit
  double exitTransmittance = 0.0;
};
inline std::optional<SphereCrossing> crossSphere(const glm::dvec3& centre, double radius,
                                                 double ior, const glm::dvec3& o,
                                                 const glm::dvec3& d) {
  const glm::dvec3 oc = o - centre;
  const double b = glm::dot(oc, d), c = glm::dot(oc, oc) - radius * radius;
  const double disc = b * b - c;
  if (disc <= 0.0) return std::nullopt;
  SphereCrossing x;
  x.entry = o + d * (-b - std::sqrt(disc));
  x.entryNormal = (x.entry - centre) / radius;
  x.entryTransmittance = 1.0 - fresnel(-glm::dot(d, x.entryNormal), ior);
  const std::optional<glm::dvec3> in = refractRay(d, x.entryNormal, 1.0 / ior);
  if (!in) return x;
  x.chord = -2.0 * glm::dot(x.entry - centre, *in);
  x.exit = x.entry + *in * x.chord;
  const glm::dvec3 n2 = (x.exit - centre) / radius;
  const std::optional<glm::dvec3> out = refractRay(*in, -n2, ior);
  if (!out) return x;  // total internal reflection (never for a sphere)
  x.exitTransmittance = 1.0 - fresnel(glm::dot(*in, n2), 1.0 / ior);
  x.out = glm::normalize(*out);
  x.refracted = true;
  return x;
}

}  // namespace ocean::reference
