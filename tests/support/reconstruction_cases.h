#pragma once
// A camera and the double-precision ground truth for depth -> position reconstruction tests.
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <gbuffer/codec.h>

namespace testsupport {

struct TestCamera {
  glm::dvec3 position;
  glm::dmat3 rotation;  // camera-to-world
  double fovY = glm::radians(60.0), aspect = 16.0 / 9.0, nearPlane = 0.1, farPlane = 2000.0;
};

// Projection for a depth convention, double precision, column-major like GL.
inline glm::dmat4 projection(const TestCamera& camera, gbuffer::DepthConvention convention) {
  const double f = 1.0 / std::tan(camera.fovY / 2.0);
  const double n = camera.nearPlane, fa = camera.farPlane;
  glm::dmat4 p(0.0);
  p[0][0] = f / camera.aspect;
  p[1][1] = f;
  p[2][3] = -1.0;
  switch (convention) {
    case gbuffer::DepthConvention::ReverseZ:  // infinite far plane, near -> 1
      p[2][2] = 0.0;
      p[3][2] = n;
      break;
    case gbuffer::DepthConvention::ForwardZeroToOne:
      p[2][2] = fa / (n - fa);
      p[3][2] = n * fa / (n - fa);
      break;
    case gbuffer::DepthConvention::ForwardNegOneToOne:
      p[2][2] = (fa + n) / (n - fa);
      p[3][2] = 2.0 * fa * n / (n - fa);
      break;
  }
  return p;
}

// Window depth in [0,1] of a view-space point, in double.
inline double windowDepth(const glm::dmat4& p, const glm::dvec3& view,
                          gbuffer::DepthConvention convention) {
  const glm::dvec4 clip = p * glm::dvec4(view, 1.0);
  const double ndcZ = clip.z / clip.w;
  return convention == gbuffer::DepthConvention::ForwardNegOneToOne ? ndcZ * 0.5 + 0.5 : ndcZ;
}

}  // namespace testsupport
