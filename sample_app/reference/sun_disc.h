#pragma once
// Directions over the sun's disc for the references' photons: the sun is not a point (0.53
// degrees across), so light reaches each point from a cone, and caustics soften with depth.
#include <glm/glm.hpp>

namespace ocean::reference {

class SunDisc {
 public:
  // `towardSun` unit; `angularRadius` radians (0: every direction is towardSun).
  SunDisc(const glm::dvec3& towardSun, double angularRadius);
  // A direction uniform over the disc from two uniform numbers in [0, 1) (the same pair gives
  // the same direction: the references stay deterministic).
  glm::dvec3 direction(double u1, double u2) const;
  double angularRadius() const { return radius_; }

 private:
  glm::dvec3 sun_, side_, up_;
  double radius_;
};

}  // namespace ocean::reference
