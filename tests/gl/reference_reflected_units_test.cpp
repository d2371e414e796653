// The traced frame reference adds reflected light in the plugin's own units: over a flat sea the
// plugin's reflected caustics (I = 1) on a quay wall facing the sun equal, per pixel and
// channel, the reference's light for flat water's mirror light read through the same G-buffer,
// and the traced reflected irradiance reproduces it within its stated noise.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include <glm/gtc/matrix_transform.hpp>

#include "caustic_light_units.h"
#include "embree_scene.h"
#include "frame_caustics_reference.h"
#include "frame_receivers.h"
#include "gbuffer_readback.h"
#include "gl_fixture.h"
#include "postfx_scene.h"
#include "postfx_test_util.h"
#include "synthetic_gbuffer.h"
#include "water_readback.h"

namespace {

using namespace ocean::reference;
using ocean::validation::SyntheticGbuffer;
using ocean::validation::SyntheticScene;
using ocean::validation::SyntheticSurface;

class ReferenceReflectedUnitsTest : public testsupport::GlTest {};

constexpr int kWidth = 64, kHeight = 40;
constexpr double kCameraY = 0.6;

// A camera 0.6 m above the level looking a little up at a quay wall 9 m away facing the sun
// (from +z, 35 degrees up), from 3 m under the water to 5 m above it; a seabed 3 m down.
SyntheticScene quayScene() {
  SyntheticScene s;
  s.width = kWidth;
  s.height = kHeight;
  s.view = glm::dmat4(glm::lookAt(glm::dvec3(0.0), glm::normalize(glm::dvec3(0.0, 0.2, -1.0)),
                                  glm::dvec3(0.0, 1.0, 0.0)));
  s.projection = postfxtest::reverseZPerspective(60.0, double(kWidth) / kHeight, 0.05, 200.0);
  s.albedoFormat = GL_RGBA16F;
  s.targetFormat = GL_RGBA32F;
  s.maxDistance = 199.0;
  SyntheticSurface wall;
  wall.point = {0.0, 0.0, -9.0};
  wall.normal = {0.0, 0.0, 1.0};
  wall.keep = {0.0, -1.0, 0.0, 5.0 - kCameraY};  // y <= 5 m
  wall.albedo = glm::vec3(0.6f, 0.5f, 0.4f);
  SyntheticSurface seabed;
  seabed.point = {0.0, -3.0 - kCameraY, 0.0};
  seabed.albedo = glm::vec3(0.5f);
  s.surfaces = {wall, seabed};
  return s;
}

TEST_F(ReferenceReflectedUnitsTest, FlatSeaReferenceLightIsThePluginsReflectedLight) {
  const SyntheticScene scene = quayScene();
  const SyntheticGbuffer gbuffer(scene);
  const GLuint water = postfxtest::makeWaterTexture(32, 1, 0.0);
  auto fx = postfxtest::makeContext(postfx::Feature::ReflectedCaustics);
  postfx::FrameDesc frame;
  frame.depth = {gbuffer.depth(), GL_DEPTH_COMPONENT32F};
  frame.normal = {gbuffer.normal(), gbuffer.normalFormat()};
  frame.albedo = {gbuffer.albedo(), GL_RGBA16F};
  frame.target = {gbuffer.target(), GL_RGBA32F};
  frame.camera.position = glm::dvec3(0.0, kCameraY, 0.0);
  frame.camera.view = glm::mat4(scene.view);
  frame.camera.projection = scene.projection;
  const double elevation = glm::radians(35.0);
  frame.sun.direction = glm::dvec3(0.0, std::sin(elevation), std::cos(elevation));
  frame.sun.irradiance = glm::vec3(2.0f, 1.5f, 1.0f);
  frame.water.level = 0.0;
  frame.water.texture = {water, GL_RGBA32F};
  frame.water.cascadeCount = 1;
  frame.water.tileSize[0] = 8.0;
  frame.water.ior = 1.333f;
  frame.reflectedCaustics.intensity = 1.3f;
  // The height layers: exact over a flat sea at every pixel (on the view's depth, exact where
  // whole triangles land, a few per cent where sub-pixel ones are summed), so the comparison is
  // of the reference's units alone.
  frame.reflectedCaustics.landing = postfx::ReflectedLanding::HeightLayers;
  ASSERT_EQ(postfx::dispatch(*fx, frame), postfx::Result::Ok) << postfx::lastError(fx.get());
  const auto added = postfxtest::readRgba(gbuffer.target(), kWidth, kHeight);

  postfx::CreateDesc create;
  GBufferCopy copy;
  std::string error;
  ASSERT_TRUE(readGBuffer(create, frame, copy, error)) << error;
  const FrameReceivers receivers = receiversOf(frame, copy);
  WaterTextureSurface surface;
  ASSERT_TRUE(surface.read(frame.water, error)) << error;
  TriangleMesh wall, seabed;
  wall.positions = {{-300, -3, -9}, {300, -3, -9}, {300, 5, -9}, {-300, 5, -9}};
  wall.normals.assign(4, glm::dvec3(0.0, 0.0, 1.0));
  wall.triangles = {{0, 1, 2}, {0, 2, 3}};
  seabed.positions = {{-300, -3, -300}, {300, -3, -300}, {300, -3, 300}, {-300, -3, 300}};
  seabed.normals.assign(4, glm::dvec3(0.0, 1.0, 0.0));
  seabed.triangles = {{0, 2, 1}, {0, 3, 2}};
  const auto embree = EmbreeScene::create({wall, seabed}, frame.camera.position, error);
  ASSERT_TRUE(embree) << error;
  FrameTraceDesc desc;
  desc.towardSun = frame.sun.direction;
  desc.ior = frame.water.ior;
  desc.reflected = true;
  const FrameTraceResult traced = traceFrameCaustics(surface, *embree, receivers, desc);

  const CausticLightUnits units = causticLightUnits(frame);
  double worstExact = 0.0, sumZ2 = 0.0;
  size_t pixels = 0, interior = 0;
  for (size_t i = 0; i < receivers.size(); ++i) {
    if (!receivers.above[i]) continue;
    ASSERT_TRUE(traced.reflectedLit[i]) << "pixel " << i;
    const double depth = receivers.depthBelow(i);
    const double distance = glm::length(copy.viewPosition[i]);
    const glm::vec3 exact = referenceReflectedLight(units, copy.albedo[i], depth,
                                                    traced.flatReflected[i], 0.0, distance);
    for (int ch = 0; ch < 3; ++ch) {
      const double plugin = double(added[i][ch]);
      ASSERT_GT(plugin, 0.0) << "pixel " << i;
      // The plugin's own flat-water exactness (its field interpolated from a grid of layers,
      // float math), as its tests state it: 2e-3.
      worstExact = std::max(worstExact, std::abs(double(exact[ch]) / plugin - 1.0));
      EXPECT_NEAR(double(exact[ch]) / plugin, 1.0, 2e-3) << "pixel " << i << " channel " << ch;
    }
    ++pixels;
    // The traced light within its noise, but where the kernel's disc crosses the wall's top
    // (a kernel estimate is low at a surface's edge; at the waterline the reference corrects it).
    const double height = -depth;
    if (height + traced.kernelRadius[i] > 5.0) continue;
    const double z = (traced.reflectedIrradiance[i] - traced.flatReflected[i]) /
                     traced.reflectedStandardError[i];
    sumZ2 += z * z;
    ++interior;
  }
  const double rmsZ = std::sqrt(sumZ2 / static_cast<double>(interior));
  std::printf(
      "flat sea, %zu wall pixels above the water: exact light within %.2e of the plugin's; "
      "traced reflected irradiance off by %.2f stated errors (rms) on the %zu below the top's "
      "kernels, noise p99 %.3f\n",
      pixels, worstExact, rmsZ, interior, traced.reflectedNoiseQuantile);
  EXPECT_GT(interior, 500u);
  EXPECT_TRUE(traced.converged);
  EXPECT_LT(rmsZ, 1.5);
  glDeleteTextures(1, &water);
}

}  // namespace
