// The traced frame reference adds light in the plugin's own units: on a flat seabed under flat
// water the plugin's added light (ray deviation: omega = 1) equals, per pixel and channel, the
// reference's light for the flat-water irradiance read through the same G-buffer, and the
// traced irradiance reproduces it within its stated noise.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "caustic_light_units.h"
#include "embree_scene.h"
#include "frame_caustics_reference.h"
#include "frame_receivers.h"
#include "gbuffer_readback.h"
#include "gl_fixture.h"
#include "postfx_scene.h"
#include "postfx_test_util.h"
#include "water_readback.h"

namespace {

using namespace ocean::reference;

class ReferenceUnitsTest : public testsupport::GlTest {};

TEST_F(ReferenceUnitsTest, FlatWaterReferenceLightIsThePluginsAddedLight) {
  postfxtest::SceneSpec spec;
  spec.width = 64;
  spec.height = 36;
  spec.sphere = false;
  spec.lookDirection = {0.0, -1.0, -0.5};
  // White: llvmpipe's shaders decode sRGB texels with an approximation (0.7 % off the exact
  // curve at linear 0.074, 0.36 % at 0.22, measured), which the read-back decodes exactly; at 1
  // both are exact, so what remains is the units alone.
  spec.albedo = glm::vec3(1.0f);
  postfxtest::Scene scene(spec);
  const GLuint water = postfxtest::makeWaterTexture(32, 2, 0.0);
  auto fx = postfxtest::makeContext(postfx::Feature::Caustics);
  postfx::FrameDesc frame = postfxtest::makeFrame(scene, water, 2);
  frame.sun.direction = glm::normalize(glm::dvec3(0.3, 1.0, -0.2));
  frame.sun.irradiance = glm::vec3(3.2f, 3.0f, 2.7f);
  scene.clearTarget(glm::vec4(0.0f));
  ASSERT_EQ(postfx::dispatch(*fx, frame), postfx::Result::Ok) << postfx::lastError(fx.get());
  const auto added = postfxtest::readRgba(scene.target, spec.width, spec.height);

  postfx::CreateDesc create;
  create.depthConvention = static_cast<postfx::DepthConvention>(spec.depthConvention);
  create.normalEncoding = static_cast<postfx::NormalEncoding>(spec.normalEncoding);
  GBufferCopy gbuffer;
  std::string error;
  ASSERT_TRUE(readGBuffer(create, frame, gbuffer, error)) << error;
  const FrameReceivers receivers = receiversOf(frame, gbuffer);
  WaterTextureSurface surface;
  ASSERT_TRUE(surface.read(frame.water, error)) << error;
  const glm::dvec3 c = frame.camera.position;
  TriangleMesh floor;
  floor.positions = {{c.x - 500, spec.floorY, c.z - 500},
                     {c.x + 500, spec.floorY, c.z - 500},
                     {c.x + 500, spec.floorY, c.z + 500},
                     {c.x - 500, spec.floorY, c.z + 500}};
  floor.normals.assign(4, glm::dvec3(0.0, 1.0, 0.0));
  floor.triangles = {{0, 2, 1}, {0, 3, 2}};
  const auto embree = EmbreeScene::create({floor}, c, error);
  ASSERT_TRUE(embree) << error;
  FrameTraceDesc desc;
  desc.towardSun = frame.sun.direction;
  desc.ior = frame.water.ior;
  const FrameTraceResult traced = traceFrameCaustics(surface, *embree, receivers, desc);
  ASSERT_TRUE(traced.converged);

  const CausticLightUnits units = causticLightUnits(frame);
  double worstExact = 0.0, sumZ2 = 0.0;
  size_t pixels = 0;
  for (size_t i = 0; i < receivers.size(); ++i) {
    ASSERT_TRUE(receivers.valid[i] && traced.lit[i]) << "pixel " << i;
    const double depth = receivers.depthBelow(i);
    const glm::vec3 exact =
        referenceCausticLight(units, gbuffer.albedo[i], depth, traced.flatIrradiance[i],
                              glm::length(gbuffer.viewPosition[i]));
    for (int ch = 0; ch < 3; ++ch) {
      const double plugin = double(added[i][ch]);
      ASSERT_GT(plugin, 0.0);
      // Float shader math against float CPU math of the same factors, a depth reconstructed from
      // D32F and an RG16_SNORM normal: 1e-4 relative.
      worstExact = std::max(worstExact, std::abs(double(exact[ch]) / plugin - 1.0));
      EXPECT_NEAR(double(exact[ch]) / plugin, 1.0, 1e-4) << "pixel " << i << " channel " << ch;
    }
    const double z = (traced.irradiance[i] - traced.flatIrradiance[i]) / traced.standardError[i];
    sumZ2 += z * z;
    ++pixels;
  }
  const double rmsZ = std::sqrt(sumZ2 / static_cast<double>(pixels));
  std::printf(
      "flat water, %zu pixels: exact light within %.2e of the plugin's; traced "
      "irradiance off by %.2f stated errors (rms), noise p99 %.3f\n",
      pixels, worstExact, rmsZ, traced.noiseQuantile);
  EXPECT_LT(rmsZ, 1.5);
  glDeleteTextures(1, &water);
}

}  // namespace
