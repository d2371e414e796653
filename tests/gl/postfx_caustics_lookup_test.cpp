// Where the caustics pass looks the water up. By default every surface samples the water where
// its light entered (the receiver moved along the refracted sun to the water plane), so the
// caustic factor at a point does not depend on the orientation of the surface there, only N.L
// does; Feature::TriplanarWalls brings back ray deviation's world-axis projections on steep
// surfaces.
#include <gtest/gtest.h>
#include <postfx/testing.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "core/frame_geometry.h"
#include "gl_fixture.h"
#include "postfx_scene.h"
#include "postfx_test_util.h"

namespace {

using postfxtest::Hit;

class PostfxCausticsLookupTest : public testsupport::GlTest {};

constexpr double kLevel = -0.5;  // world; the camera is at y = -2

// Floor and a sphere entirely under the water: every orientation facing the light, on screen.
postfxtest::SceneSpec submergedSphereScene() {
  postfxtest::SceneSpec s;
  s.width = 160;
  s.height = 90;
  s.normalEncoding = 1;  // world xyz RGBA16F: the same texture format for the "all up" normals
  s.lookDirection = {0.0, -0.3, -1.0};
  s.sphereCenter = {0.5, -3.5, -7.0};
  s.sphereRadius = 2.0;
  return s;
}

// The same G-buffer with every normal replaced by straight up.
GLuint makeUpNormals(int width, int height) {
  GLuint t = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &t);
  glTextureStorage2D(t, 1, GL_RGBA16F, width, height);
  const std::vector<glm::vec4> up(static_cast<size_t>(width * height), glm::vec4(0, 1, 0, 0));
  glTextureSubImage2D(t, 0, 0, 0, width, height, GL_RGBA, GL_FLOAT, up.data());
  return t;
}

struct OrientationChange {
  double maxDiff = 0.0;  // largest |factor with the true normal - factor facing up|
  int compared = 0, steep = 0;
};

// Caustic factor (raw output / N.L) with the scene's normals against the same points facing up,
// over underwater pixels that face the light well enough (N.L > 0.2) for the division to be
// well conditioned; steep pixels are those more than 45 degrees from horizontal.
OrientationChange orientationChange(postfx::Feature features, const postfxtest::Scene& scene,
                                    GLuint water, GLuint upNormals) {
  auto fx = postfxtest::makeContext(features | postfxtest::kRaw, 0, 1);
  postfx::FrameDesc frame = postfxtest::makeFrame(scene, water, 1, {}, kLevel);
  frame.water.tileSize[0] = 10.0;
  const int w = scene.spec().width, h = scene.spec().height;
  EXPECT_EQ(postfx::dispatch(*fx, frame), postfx::Result::Ok) << postfx::lastError(fx.get());
  const auto own = postfxtest::readRed(postfx::testing::rawCausticTexture(*fx), w, h);
  frame.normal = {upNormals, GL_RGBA16F};
  EXPECT_EQ(postfx::dispatch(*fx, frame), postfx::Result::Ok) << postfx::lastError(fx.get());
  const auto facingUp = postfxtest::readRed(postfx::testing::rawCausticTexture(*fx), w, h);

  const glm::dvec3 toLight =
      -postfx::detail::refractedSunDown(frame.sun.direction, frame.water.ior);
  const double levelRel = kLevel - scene.spec().camera.y;
  OrientationChange change;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const postfxtest::PixelTruth& t = scene.truth(x, y);
      const double nDotL = glm::dot(t.normal, toLight);
      if (t.hit == Hit::Sky || t.position.y > levelRel - 0.05 || nDotL < 0.2) continue;
      const size_t i = static_cast<size_t>(y * w + x);
      const double diff = std::abs(double(own[i]) / nDotL - double(facingUp[i]) / toLight.y);
      change.maxDiff = std::max(change.maxDiff, diff);
      ++change.compared;
      if (std::abs(t.normal.y) < std::sqrt(0.5)) ++change.steep;
    }
  }
  return change;
}

TEST_F(PostfxCausticsLookupTest, FactorDependsOnThePointNotOnTheSurfaceOrientation) {
  postfxtest::Scene scene(submergedSphereScene());
  // Slopes of 0.12 make the factor swing over most of [0, 1] across a period (tau 800).
  const GLuint water = postfxtest::makeLevelIndependentWaterTexture(512, 0.12);
  const GLuint upNormals = makeUpNormals(scene.spec().width, scene.spec().height);

  const OrientationChange lightEntry =
      orientationChange(postfx::Feature::None, scene, water, upNormals);
  const OrientationChange triplanar =
      orientationChange(postfx::Feature::TriplanarWalls, scene, water, upNormals);
  std::printf(
      "factor change when the normal turns up: along the light %.5f, tri-planar %.5f "
      "(%d pixels, %d steeper than 45 degrees)\n",
      lightEntry.maxDiff, triplanar.maxDiff, lightEntry.compared, lightEntry.steep);
  // The scene must hold steep lit surfaces, or the comparison proves nothing.
  EXPECT_GT(lightEntry.compared, 3000);
  EXPECT_GT(lightEntry.steep, 300);
  // Along the light: the same point gets the same factor. Left over: R16F raw (1e-3 relative),
  // the RGBA16F normal in N.L (1e-3 relative, divided by N.L >= 0.2) and the level-independent
  // texture's bilinear error (< 1e-3 of the slope, ~3e-3 of the factor at tau 800).
  EXPECT_LT(lightEntry.maxDiff, 0.015);
  // Tri-planar: steep surfaces read other points of the water, so their factor changes.
  EXPECT_GT(triplanar.maxDiff, 0.1);
  const GLuint textures[] = {water, upNormals};
  glDeleteTextures(2, textures);
}

}  // namespace
