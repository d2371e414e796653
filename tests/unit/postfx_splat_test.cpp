// The object caustics' splat shape (shaders/postfx/object_caustics/postfx_object_caustics.h) on the
// CPU: each ray's Gaussian conserves its flux whatever its shape, a lattice of rays that diverges
// adds up to smooth light instead of rings, and a converging direction keeps its sharpness.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/shared_math.h"

namespace {

namespace sh = postfx::shared;

// The sum over the texels the splat fragment shader writes (the sprite square, cut at 3 sigma
// per axis), centre anywhere in its texel.
double spriteSum(const glm::vec2& centre, const glm::vec3& covariance) {
  const float sx = std::sqrt(covariance.x), sy = std::sqrt(covariance.z);
  const int half = int(std::ceil(3.0f * std::max(sx, sy))) + 1;
  double sum = 0.0;
  for (int y = -half; y <= half; ++y) {
    for (int x = -half; x <= half; ++x) {
      const glm::vec2 texel(std::floor(centre.x) + float(x) + 0.5f,
                            std::floor(centre.y) + float(y) + 0.5f);
      const glm::vec2 o = texel - centre;
      if (std::abs(o.x) > 3.0f * sx || std::abs(o.y) > 3.0f * sy) continue;  // as the shader
      sum += double(sh::splatWeight(o, covariance));
    }
  }
  return sum;
}

TEST(PostfxSplatShape, WithoutNeighboursTheSplatIsTheSplatRadius) {
  const glm::vec3 c = sh::splatCovariance(1.5f, glm::vec2(0.0f), glm::vec2(0.0f), 16.0f, 0.0f);
  EXPECT_FLOAT_EQ(c.x, 2.25f);
  EXPECT_FLOAT_EQ(c.y, 0.0f);
  EXPECT_FLOAT_EQ(c.z, 2.25f);
}

TEST(PostfxSplatShape, EveryShapeConservesTheRaysFlux) {
  // Round, elongated along an axis, elongated along a diagonal, at the cap; centres anywhere.
  const glm::vec2 lattices[][2] = {{{0.0f, 0.0f}, {0.0f, 0.0f}},
                                   {{6.0f, 0.0f}, {0.0f, 0.3f}},
                                   {{4.0f, 4.0f}, {-0.2f, 0.2f}},
                                   {{3.0f, 1.0f}, {-1.0f, 5.0f}},
                                   {{400.0f, 10.0f}, {0.0f, 0.5f}}};
  for (const auto& l : lattices) {
    for (float roundness : {0.0f, 1.0f}) {
      const glm::vec3 c = sh::splatCovariance(1.0f, l[0], l[1], 16.0f, roundness);
      for (const glm::vec2 centre :
           {glm::vec2(10.5f, 10.5f), glm::vec2(10.13f, 10.77f), glm::vec2(10.0f, 10.99f)}) {
        // erf(3/sqrt 2)^2 of a Gaussian lies in the square; a correlated one fills more of it
        // (up to 0.9973 / 0.9946), and a texel centre exactly on the 3-sigma line is kept
        // (+0.49 % for sigma 1 centred on a texel): within 0.6 %.
        EXPECT_NEAR(spriteSum(centre, c), 1.0, 0.006)
            << "lattice (" << l[0].x << ", " << l[0].y << ") (" << l[1].x << ", " << l[1].y
            << "), roundness " << roundness << ", centre " << centre.x << ", " << centre.y;
      }
    }
  }
}

// Relative peak-to-peak ripple of the light of an infinite lattice of rays (vectors a, b, one
// unit of flux each) sampled over one cell, splatted with covariance `c`.
double latticeRipple(const glm::vec2& a, const glm::vec2& b, const glm::vec3& c) {
  double lo = 1e30, hi = 0.0;
  for (int sy = 0; sy < 8; ++sy) {
    for (int sx = 0; sx < 8; ++sx) {
      const glm::vec2 p = a * (float(sx) / 8.0f) + b * (float(sy) / 8.0f);
      double sum = 0.0;
      for (int j = -12; j <= 12; ++j)
        for (int i = -12; i <= 12; ++i)
          sum += double(sh::splatWeight(p - (a * float(i) + b * float(j)), c));
      lo = std::min(lo, sum);
      hi = std::max(hi, sum);
    }
  }
  return (hi - lo) / (0.5 * (hi + lo));
}

TEST(PostfxSplatShape, DivergingRaysAddUpToSmoothLight) {
  // Rays landing 3-5 texels apart on a sheared lattice: the divergent part of a lens's caustic.
  const glm::vec2 a(3.2f, 0.7f), b(-0.9f, 4.6f);
  const glm::vec3 widened = sh::splatCovariance(1.0f, a, b, 16.0f, 0.0f);
  const glm::vec3 narrow(1.0f, 0.0f, 1.0f);  // the splat radius alone: the rings users saw
  const double ripple = latticeRipple(a, b, widened), rings = latticeRipple(a, b, narrow);
  EXPECT_LT(ripple, 0.03) << "a lattice splatted at half its spacing is smooth";
  EXPECT_GT(rings, 0.3) << "the test must see the rings a fixed splat radius leaves";
}

TEST(PostfxSplatShape, ConvergingDirectionStaysAsNarrowAsTheSplatRadius) {
  // Rays 0.1 texel apart along x (converging onto a caustic line), 6 texels along y.
  const glm::vec3 c =
      sh::splatCovariance(1.0f, glm::vec2(0.1f, 0.0f), glm::vec2(0.0f, 6.0f), 16.0f, 0.0f);
  EXPECT_NEAR(c.x, 1.0f + 0.25f * 0.01f, 1e-4f);
  EXPECT_NEAR(c.z, 1.0f + 9.0f, 1e-4f);
  // Made round (a dim, divergent ray), both axes take the wider one.
  const glm::vec3 round =
      sh::splatCovariance(1.0f, glm::vec2(0.1f, 0.0f), glm::vec2(0.0f, 6.0f), 16.0f, 1.0f);
  EXPECT_NEAR(round.x, round.z, 1e-4f);
}

TEST(PostfxSplatShape, WidthIsBoundedAlongEachAxisWithoutLosingTheOther) {
  // A ray fanning out 1000 texels along x and 8 along y: x is capped at 16 texels, y keeps 4.
  const glm::vec2 a(1000.0f, 0.0f), b(0.0f, 8.0f);
  const glm::vec3 c = sh::splatCovariance(1.0f, a, b, 16.0f, 0.0f);
  EXPECT_NEAR(c.x, 1.0f + 256.0f, 1e-2f);
  EXPECT_NEAR(c.z, 1.0f + 16.0f, 1e-2f);
  for (float v : {c.x, c.y, c.z}) EXPECT_TRUE(std::isfinite(v));
}

}  // namespace
