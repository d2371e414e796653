// The TileIrradiance scatter's point footprints: where the points are at least as dense as the
// water's texels, each point's flux covers where its cell lands (its neighbours' landings), so
// light that diverges stays a smooth field instead of a grid of bilinear dots a few texels
// apart, and the flux is the same. The same smooth wave is drawn both ways: on a texture as
// fine as the points (footprints) and on one twice as fine (bilinear split of each cell's mean).
#include <gtest/gtest.h>
#include <postfx/testing.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "gl_fixture.h"
#include "postfx_scene.h"
#include "postfx_test_util.h"

namespace {

using postfxtest::Hit;
using postfxtest::kRaw;

constexpr double kTile = 1.0;         // m
constexpr int kPeriods = 2;           // wave periods per tile, along x
constexpr double kAmplitude = 0.017;  // m: the troughs spread the light ~3x at 3 m

// One plane wave along x, exact slopes and heights at each texel, whole periods per tile.
GLuint makePlaneWave(int size) {
  std::vector<glm::vec4> texels(static_cast<size_t>(size * size));
  const double k = 6.283185307179586 * kPeriods / kTile;
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      const double px = (x + 0.5) / size * kTile;
      texels[static_cast<size_t>(y * size + x)] =
          glm::vec4(float(kAmplitude * k * std::cos(k * px)), 0.0f,
                    float(kAmplitude * std::sin(k * px)), 1.0f);
    }
  }
  return postfxtest::makeWaterTextureFromTexels(size, texels);
}

struct DarkField {
  double mean = 0.0;       // raw light over every floor pixel
  double roughness = 0.0;  // mean |second difference along x| over the dark pixels, / their mean
  int darkPixels = 0;
};

class PostfxTileFootprintTest : public testsupport::GlTest {
 protected:
  DarkField draw(int waterTexels) {
    postfxtest::SceneSpec spec;
    spec.sphere = false;
    spec.width = 192;
    spec.height = 108;
    spec.camera = {0.0, -1.0, 0.0};
    spec.lookDirection = {0.0, -1.0, -1e-3};  // straight down
    spec.floorY = -3.0;
    postfxtest::Scene scene(spec);
    const GLuint water = makePlaneWave(waterTexels);
    postfxtest::ContextPtr fx = postfxtest::makeContext(kRaw);
    postfx::FrameDesc frame = postfxtest::makeFrame(scene, water, 1);
    frame.water.tileSize[0] = kTile;
    frame.sun.direction = glm::dvec3(0.0, 1.0, 0.0);
    frame.sun.angularDiameterDegrees = 0.0f;  // nothing but the points' own reconstruction
    frame.caustics.model = postfx::CausticsModel::TileIrradiance;
    frame.caustics.tileUnresolvedSpread = false;
    frame.caustics.tileMinModulation = 0.0f;
    frame.caustics.tileResolution = 64;
    frame.caustics.tileLookupResolution = postfx::CausticsLookupResolution::Full;
    frame.caustics.maxReceiverDepth = 3.0f;  // the deepest layer is the floor's depth
    EXPECT_EQ(postfx::dispatch(*fx, frame), postfx::Result::Ok) << postfx::lastError(fx.get());
    const std::vector<float> raw =
        postfxtest::readRed(postfx::testing::rawCausticTexture(*fx), spec.width, spec.height);
    glDeleteTextures(1, &water);
    DarkField d;
    double sum = 0.0, darkSum = 0.0, rough = 0.0;
    int n = 0;
    for (int y = 0; y < spec.height; ++y) {
      for (int x = 1; x + 1 < spec.width; ++x) {
        auto at = [&](int i) { return double(raw[static_cast<size_t>(y * spec.width + i)]); };
        if (scene.truth(x - 1, y).hit != Hit::Floor || scene.truth(x, y).hit != Hit::Floor ||
            scene.truth(x + 1, y).hit != Hit::Floor)
          continue;
        sum += at(x);
        ++n;
        // Where the troughs spread the light out, away from the folds' edges.
        if (std::max({at(x - 1), at(x), at(x + 1)}) < 0.5) {
          darkSum += at(x);
          rough += std::abs(at(x - 1) - 2.0 * at(x) + at(x + 1));
          ++d.darkPixels;
        }
      }
    }
    d.mean = n > 0 ? sum / n : 0.0;
    d.roughness = darkSum > 0.0 ? rough / darkSum : 0.0;
    return d;
  }
};

TEST_F(PostfxTileFootprintTest, DivergingLightIsSmoothAndKeepsItsFlux) {
  const DarkField footprints = draw(64);  // points as dense as the texels
  const DarkField bilinear = draw(128);   // each point the mean of 2x2 texels
  std::printf(
      "mean raw light: footprints %.4f, bilinear %.4f; dark pixels %d / %d, roughness "
      "%.4f / %.4f\n",
      footprints.mean, bilinear.mean, footprints.darkPixels, bilinear.darkPixels,
      footprints.roughness, bilinear.roughness);
  ASSERT_GT(footprints.darkPixels, 2000) << "the test needs light spread out by the troughs";
  ASSERT_GT(bilinear.darkPixels, 2000);
  // The same flux: the floor spans several periods, whose mean light is flat water's.
  EXPECT_NEAR(footprints.mean / bilinear.mean, 1.0, 0.02);
  // Bilinear splats of points ~3 texels apart leave dots; footprints leave a smooth field.
  EXPECT_GT(bilinear.roughness, 10.0 * footprints.roughness);
  EXPECT_LT(footprints.roughness, 0.05);
}

}  // namespace
