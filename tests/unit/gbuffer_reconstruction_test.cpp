// Depth -> world position reconstruction against a double-precision reference, for every depth
// convention, at near, mid and far depths, at the origin and 1e6 m from it.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>

#include "reconstruction_cases.h"

namespace {

using gbuffer::DepthConvention;
using testsupport::TestCamera;

struct Measured {
  double reconstruction = 0.0;  // float math vs double math on the same stored depth (relative)
  double roundTrip = 0.0;       // including the D32F storage of depth (relative)
};

// Reconstructs world position the way a shader does: float, camera-relative, then adds the
// double camera position on the CPU side of the comparison.
glm::dvec3 reconstructFloat(const TestCamera& camera, const glm::dmat4& p, glm::vec2 uv,
                            float depth, DepthConvention convention) {
  const gbuffer::ProjectionParams params = gbuffer::projectionParams(p, convention);
  const glm::vec3 view = gbuffer::shared::viewPositionFromDepth(uv, depth, params.xy, params.z,
                                                                static_cast<int>(convention));
  const glm::vec3 relative = glm::mat3(camera.rotation) * view;
  return camera.position + glm::dvec3(relative);
}

Measured measure(const TestCamera& camera, DepthConvention convention, double distance) {
  const glm::dmat4 p = testsupport::projection(camera, convention);
  Measured worst;
  // A spread of pixels across the screen, including corners.
  for (double u : {0.01, 0.25, 0.5, 0.77, 0.99}) {
    for (double v : {0.02, 0.5, 0.98}) {
      const glm::dvec3 ndc(u * 2.0 - 1.0, v * 2.0 - 1.0, 0.0);
      const glm::dvec3 view(ndc.x * distance / p[0][0], ndc.y * distance / p[1][1], -distance);
      const glm::dvec3 truth = camera.position + camera.rotation * view;
      const double exactDepth = testsupport::windowDepth(p, view, convention);
      const float storedDepth = static_cast<float>(exactDepth);  // what D32F holds
      const glm::vec2 uv(static_cast<float>(u), static_cast<float>(v));

      // Reference on the same stored depth, in double: isolates the float math of the shader.
      const double ndcZ = convention == DepthConvention::ForwardNegOneToOne
                              ? double(storedDepth) * 2.0 - 1.0
                              : double(storedDepth);
      const double viewZ = -p[3][2] / (ndcZ + p[2][2]);
      const glm::dvec3 refView(-viewZ * (double(uv.x) * 2.0 - 1.0) / p[0][0],
                               -viewZ * (double(uv.y) * 2.0 - 1.0) / p[1][1], viewZ);
      const glm::dvec3 reference = camera.position + camera.rotation * refView;

      const glm::dvec3 got = reconstructFloat(camera, p, uv, storedDepth, convention);
      worst.reconstruction =
          std::max(worst.reconstruction, glm::length(got - reference) / distance);
      worst.roundTrip = std::max(worst.roundTrip, glm::length(got - truth) / distance);
    }
  }
  return worst;
}

const char* name(DepthConvention convention) {
  switch (convention) {
    case DepthConvention::ReverseZ:
      return "reverse-Z [0,1]";
    case DepthConvention::ForwardZeroToOne:
      return "forward [0,1]";
    case DepthConvention::ForwardNegOneToOne:
      return "forward [-1,1]";
  }
  return "?";
}

TEST(GbufferReconstruction, RoundTripAgainstDoubleReference) {
  const std::array conventions = {DepthConvention::ReverseZ, DepthConvention::ForwardZeroToOne,
                                  DepthConvention::ForwardNegOneToOne};
  const std::array<double, 3> distances = {0.5, 40.0, 1500.0};  // near, mid, far (metres)
  const std::array<glm::dvec3, 2> origins = {glm::dvec3(0.0), glm::dvec3(1e6, -12.0, -1e6)};
  TestCamera camera;
  // A tilted camera, so every axis of the rotation takes part.
  camera.rotation = glm::dmat3(glm::rotate(glm::dmat4(1.0), 0.4, glm::dvec3(0.3, 1.0, 0.2)));

  double worstReconstruction = 0.0;
  for (const DepthConvention convention : conventions) {
    for (const glm::dvec3& origin : origins) {
      for (const double distance : distances) {
        camera.position = origin;
        const Measured m = measure(camera, convention, distance);
        std::printf(
            "%-15s origin %8.0e m  distance %7.1f m: reconstruction %.2e  round trip %.2e"
            " (relative)\n",
            name(convention), origin.x, distance, m.reconstruction, m.roundTrip);
        worstReconstruction = std::max(worstReconstruction, m.reconstruction);
        // Float math on a stored depth: a few ulps of the result, whatever the convention,
        // distance or world offset (the offset never enters float math).
        EXPECT_LT(m.reconstruction, 1e-6) << name(convention) << " at " << distance << " m";
        // Storage matters: reverse-Z keeps D32F's relative precision at every distance; forward
        // conventions lose it with distance (depth crowds near 1), which is why reverse-Z is
        // the recommended host setup. Bounds per convention from the depth quantization.
        const double storageBound = convention == DepthConvention::ReverseZ
                                        ? 1e-6
                                        : 1.5e-7 * distance / camera.nearPlane + 1e-6;
        EXPECT_LT(m.roundTrip, storageBound) << name(convention) << " at " << distance << " m";
      }
    }
  }
  std::printf("worst reconstruction error: %.2e of the distance\n", worstReconstruction);
  RecordProperty("worst_relative_reconstruction_error", std::to_string(worstReconstruction));
}

TEST(GbufferReconstruction, SkyDepthIsRecognisedPerConvention) {
  using gbuffer::shared::isSkyDepth;
  EXPECT_TRUE(isSkyDepth(0.0f, gbuffer::shared::DEPTH_REVERSE_Z));
  EXPECT_FALSE(isSkyDepth(1e-7f, gbuffer::shared::DEPTH_REVERSE_Z));
  EXPECT_TRUE(isSkyDepth(1.0f, gbuffer::shared::DEPTH_FORWARD_ZERO_ONE));
  EXPECT_FALSE(isSkyDepth(0.9999f, gbuffer::shared::DEPTH_FORWARD_NEG_ONE));
  EXPECT_TRUE(
      isSkyDepth(std::numeric_limits<float>::quiet_NaN(), gbuffer::shared::DEPTH_REVERSE_Z));
}

}  // namespace
