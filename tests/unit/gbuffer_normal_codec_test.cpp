// Normal encodings: round trip error over the sphere, and garbage texels decode to zero
// (never NaN) so a pass can reject them.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>

#include <gbuffer/codec.h>

namespace {

using namespace gbuffer::shared;

// RG16_SNORM storage: what the octahedral encoding goes through in the sample's G-buffer.
glm::vec2 quantizeSnorm16(glm::vec2 v) {
  return glm::round(glm::clamp(v, -1.0f, 1.0f) * 32767.0f) / 32767.0f;
}

TEST(GbufferNormalCodec, OctahedralRoundTripOverTheSphere) {
  double worstDegrees = 0.0;
  const int steps = 181;
  for (int i = 0; i < steps; ++i) {
    for (int j = 0; j < 2 * steps; ++j) {
      const double theta = M_PI * i / (steps - 1), phi = M_PI * j / steps;
      const glm::vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta),
                        std::sin(theta) * std::sin(phi));
      const glm::vec3 decoded = octDecode(quantizeSnorm16(octEncode(n)));
      ASSERT_NEAR(glm::length(decoded), 1.0f, 1e-5f);
      const double cosAngle = std::clamp(double(glm::dot(decoded, n)), -1.0, 1.0);
      worstDegrees = std::max(worstDegrees, std::acos(cosAngle) * 180.0 / M_PI);
    }
  }
  std::printf("octahedral RG16_SNORM worst angular error: %.4f degrees\n", worstDegrees);
  // 16-bit octahedral: the step of 2/32767 across the folded square is ~0.035 degrees at its
  // coarsest (measured); a lost bit or a wrong fold would show as 0.07 degrees or far more.
  EXPECT_LT(worstDegrees, 0.05);
}

TEST(GbufferNormalCodec, EveryEncodingRoundTrips) {
  const glm::vec3 n = glm::normalize(glm::vec3(0.3f, -0.8f, 0.52f));
  for (int encoding : {NORMAL_OCTAHEDRAL, NORMAL_XYZ, NORMAL_XYZ_UNORM}) {
    const glm::vec3 decoded = decodeNormal(encodeNormal(n, encoding), encoding);
    EXPECT_NEAR(glm::distance(decoded, n), 0.0f, 1e-5f) << "encoding " << encoding;
  }
}

TEST(GbufferNormalCodec, GarbageTexelsDecodeToZeroNotNan) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  for (int encoding : {NORMAL_OCTAHEDRAL, NORMAL_XYZ}) {
    for (const glm::vec4 texel : {glm::vec4(0.0f), glm::vec4(nan), glm::vec4(inf, 0, 0, 0)}) {
      const glm::vec3 decoded = decodeNormal(texel, encoding);
      EXPECT_FALSE(std::isnan(decoded.x) || std::isnan(decoded.y) || std::isnan(decoded.z));
      if (encoding == NORMAL_XYZ) {
        EXPECT_EQ(decoded, glm::vec3(0.0f));
      }
    }
  }
  EXPECT_EQ(decodeNormal(glm::vec4(0.5f, 0.5f, 0.5f, 1.0f), NORMAL_XYZ_UNORM), glm::vec3(0.0f));
}

}  // namespace
