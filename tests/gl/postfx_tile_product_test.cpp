// The TileIrradiance model multiplies one field per cascade, each clamped to
// min(maxIrradiance, 1024). Where several cascades focus on the same receiver that product can
// pass a half float's range (65504): the half-resolution lookups pack it into halves and an
// RGBA16F target stores halves, so it would become inf there, and inf times a zero upsample
// weight NaN. A stiff host water (four identical cascades, each an egg crate focused exactly on
// the floor, no sun disc, no spread, the clamp raised to its maximum) must still give finite
// light everywhere, at both lookup resolutions, bounded by the clamp each field has (1024).
#include <gtest/gtest.h>
#include <postfx/testing.h>

#include <cmath>
#include <vector>

#include "gl_fixture.h"
#include "postfx_scene.h"
#include "postfx_test_util.h"

namespace {

using postfxtest::Hit;
using postfxtest::kRaw;

constexpr double kTile = 4.0;   // m, every cascade
constexpr int kPeriods = 2;     // per tile, along x and z
constexpr double kDepth = 3.0;  // m: the floor, the deepest layer and each cascade's focus
constexpr int kCascades = 4;    // postfx::kMaxCascades
constexpr int kWaterTexels = 128;

// h = A cos(kx) cos(kz) at every texel, exact slopes. A crest's curvature is A k^2 along both
// axes; a thin lens of slope-deflection (1 - 1/n) focuses it at 1 / ((1 - 1/n) A k^2).
GLuint makeFocusingCascades() {
  const double k = 6.283185307179586 * kPeriods / kTile;
  const double n = 1.333;
  const double amplitude = 1.0 / ((1.0 - 1.0 / n) * k * k * kDepth);
  const size_t perCascade = static_cast<size_t>(kWaterTexels * kWaterTexels);
  std::vector<glm::vec4> texels(perCascade * kCascades);
  for (int y = 0; y < kWaterTexels; ++y) {
    for (int x = 0; x < kWaterTexels; ++x) {
      const double px = (x + 0.5) / kWaterTexels * kTile, pz = (y + 0.5) / kWaterTexels * kTile;
      const glm::vec4 texel(float(-amplitude * k * std::sin(k * px) * std::cos(k * pz)),
                            float(-amplitude * k * std::cos(k * px) * std::sin(k * pz)),
                            float(amplitude * std::cos(k * px) * std::cos(k * pz)), 1.0f);
      for (int c = 0; c < kCascades; ++c)  // the same sea in every cascade
        texels[c * perCascade + static_cast<size_t>(y * kWaterTexels + x)] = texel;
    }
  }
  return postfxtest::makeWaterTextureFromTexels(kWaterTexels, texels);
}

struct Light {
  bool finite = true;
  double maxRaw = 0.0;  // the raw factor's largest value over the floor
  int floorPixels = 0;
};

class PostfxTileProductTest : public testsupport::GlTest {
 protected:
  Light draw(postfx::CausticsLookupResolution lookup, GLenum targetFormat) {
    postfxtest::SceneSpec spec;
    spec.sphere = false;
    spec.width = 128;
    spec.height = 96;
    spec.camera = {0.0, -0.5, 0.0};
    spec.lookDirection = {0.0, -1.0, -1e-3};  // straight down on the focused crests
    spec.floorY = -kDepth;
    postfxtest::Scene scene(spec, targetFormat);
    scene.clearTarget(glm::vec4(0.0f));
    const GLuint water = makeFocusingCascades();
    postfxtest::ContextPtr fx = postfxtest::makeContext(kRaw);
    postfx::FrameDesc frame = postfxtest::makeFrame(scene, water, kCascades);
    for (int c = 0; c < kCascades; ++c) frame.water.tileSize[c] = kTile;
    frame.sun.direction = glm::dvec3(0.0, 1.0, 0.0);
    frame.sun.angularDiameterDegrees = 0.0f;
    frame.caustics.model = postfx::CausticsModel::TileIrradiance;
    frame.caustics.tileUnresolvedSpread = false;
    frame.caustics.tileMinModulation = 0.0f;
    frame.caustics.tileResolution = 128;
    frame.caustics.tileLookupResolution = lookup;
    frame.caustics.maxReceiverDepth = float(kDepth);
    frame.caustics.maxIrradiance = 1e4f;
    EXPECT_EQ(postfx::dispatch(*fx, frame), postfx::Result::Ok) << postfx::lastError(fx.get());
    const std::vector<float> raw =
        postfxtest::readRed(postfx::testing::rawCausticTexture(*fx), spec.width, spec.height);
    const std::vector<glm::vec4> target =
        postfxtest::readRgba(scene.target, spec.width, spec.height);
    glDeleteTextures(1, &water);
    Light l;
    for (int y = 0; y < spec.height; ++y) {
      for (int x = 0; x < spec.width; ++x) {
        const size_t i = static_cast<size_t>(y * spec.width + x);
        const glm::vec4 t = target[i];
        if (!std::isfinite(raw[i]) || !std::isfinite(t.r) || !std::isfinite(t.g) ||
            !std::isfinite(t.b) || !std::isfinite(t.a))
          l.finite = false;
        if (scene.truth(x, y).hit != Hit::Floor) continue;
        ++l.floorPixels;
        l.maxRaw = std::max(l.maxRaw, double(raw[i]));
      }
    }
    return l;
  }
};

TEST_F(PostfxTileProductTest, FocusedCascadesStayFiniteInHalfFloats) {
  using postfx::CausticsLookupResolution;
  const Light half = draw(CausticsLookupResolution::Half, GL_RGBA16F);
  const Light full = draw(CausticsLookupResolution::Full, GL_RGBA16F);
  const Light full32 = draw(CausticsLookupResolution::Full, GL_RGBA32F);
  std::printf("largest raw factor: half %.1f, full %.1f, full into RGBA32F %.1f (%d floor px)\n",
              half.maxRaw, full.maxRaw, full32.maxRaw, full32.floorPixels);
  ASSERT_GT(full32.floorPixels, 10000);
  // The scene is as stiff as intended: the crests focus far past one cascade's default clamp.
  EXPECT_GT(full32.maxRaw, 1000.0);
  EXPECT_TRUE(half.finite);
  EXPECT_TRUE(full.finite);
  EXPECT_TRUE(full32.finite);
  // The product is clamped as each field is (TILE_MAX_IRRADIANCE, postfx_tile_irradiance.h).
  EXPECT_LE(full32.maxRaw, 1024.0 * 1.001);
  EXPECT_LE(half.maxRaw, 1024.0 * 1.001);
}

}  // namespace
