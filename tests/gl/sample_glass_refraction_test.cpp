// The sample's glass shows what is behind it, refracted, not a surface of its own: a glass ball
// under water in front of a wall whose left half is pale and right half dark. The wall stands far
// beyond the ball's focus (a ball lens of relative index n = 1.5 / 1.33 focuses
// n r / (2 (n - 1)) = 2.2 m from its centre for r = 0.5 m), so the ball shows it upside down and
// mirrored: the left of the silhouette sees the dark half, the right the pale half. The same
// ball made opaque shows neither; without a ball the same pixels show the wall as it is. In
// open water the ball shows the water around it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <gl_fixture.h>
#include <scene/asset_models.h>
#include <scene/mesh_builders.h>
#include <scene/model.h>

#include <glm/gtc/matrix_transform.hpp>

#include "camera.h"
#include "options.h"
#include "plugin_setup.h"
#include "renderer.h"
#include "sample_flat_water.h"

namespace {

constexpr int kWidth = 256, kHeight = 144;
constexpr double kBallRadius = 0.5;
const glm::dvec3 kEye(0.0, -3.0, 0.0);
const glm::dvec3 kBall(0.0, -3.0, -3.0);  // 3 m ahead of the camera, which looks along -z
constexpr double kWallZ = -11.0;          // 8 m behind the ball, 3.6 focal lengths

enum class Ball { None, Glass, Opaque };
enum class Backdrop { Wall, OpenWater };

ocean_scene::Model wallScene(Ball ball, Backdrop backdrop = Backdrop::Wall) {
  using namespace ocean_scene;
  Model model;
  auto addWall = [&](float centreX, glm::vec3 albedo, const std::string& name) {
    Material m;
    m.name = name;
    m.baseColor = albedo;
    m.metallic = 0.0f;
    model.materials.push_back(m);
    Mesh mesh = makeBox(glm::vec3(6.0f, 6.0f, 0.2f), name);
    mesh.material = uint32_t(model.materials.size() - 1);
    addMeshInstance(model, std::move(mesh),
                    glm::translate(glm::mat4(1.0f), glm::vec3(centreX, -3.0f, float(kWallZ))),
                    name);
  };
  if (backdrop == Backdrop::Wall) {
    addWall(-6.0f, glm::vec3(0.9f), "pale_half");  // x in [-12, 0]
    addWall(6.0f, glm::vec3(0.02f), "dark_half");  // x in [0, 12]
  }
  if (ball != Ball::None) {
    Model sphere = makeGlassSphereModel();
    if (ball == Ball::Opaque) {
      sphere.materials[0].transmission = 0.0f;
      sphere.materials[0].baseColor = glm::vec3(0.5f);
    }
    appendModel(model, sphere, glm::translate(glm::mat4(1.0f), glm::vec3(kBall)));
  }
  return model;
}

ocean::Camera camera() {
  ocean::Camera c;
  c.position = kEye;
  c.yaw = 0.0;
  c.pitch = 0.0;
  c.fovY = glm::radians(40.0);
  return c;
}

class SampleGlassRefraction : public testsupport::GlTest {
 protected:
  // godRays: the plugin's shafts in the water column too (they light the open water).
  std::vector<float> render(Ball ball, Backdrop backdrop = Backdrop::Wall, bool godRays = false) {
    const ocean::RenderSettings settings = sampletest::flatWaterRenderSettings(kWidth, kHeight);
    std::string error;
    const ocean_scene::Model scene = wallScene(ball, backdrop);
    auto renderer = ocean::Renderer::create(settings, scene, error);
    EXPECT_TRUE(renderer) << error;
    if (!renderer) return {};
    // Flat light on the wall, no light of the ball's own.
    ocean::Options options = sampletest::flatWaterOptions();
    options.godRays = godRays;
    auto plugin = ocean::PluginSetup::create(*renderer, options, false, error);
    EXPECT_TRUE(plugin) << error;
    if (!plugin) return {};
    ocean::Sun sun;
    // Behind the camera, so the wall's face is lit; the ball's shadow lands 14 m below the
    // view's centre on the wall (the refracted sun climbs 61 degrees).
    sun.elevation = glm::radians(50.0);
    sun.azimuth = glm::radians(180.0);
    EXPECT_TRUE(renderer->render({camera(), sun, 0.0}, error)) << error;
    expectNoGlErrors("sample glass refraction");
    return renderer->readRadiance();
  }
};

double luminance(const std::vector<float>& image, size_t i) {
  return 0.2126 * double(image[i * 4]) + 0.7152 * double(image[i * 4 + 1]) +
         0.0722 * double(image[i * 4 + 2]);
}

// Pixels well inside the ball's silhouette (radial position 0.2..0.7 of its angular radius, away
// from the Fresnel rim), split by the side of the vertical centre line they lie on.
struct Halves {
  std::vector<size_t> left, right;
};

Halves ballHalves() {
  const ocean::Camera c = camera();
  const glm::dmat4 projection = c.projection(double(kWidth) / kHeight);
  const glm::dvec3 centre = glm::normalize(kBall - kEye);
  const double angularRadius = std::asin(kBallRadius / glm::length(kBall - kEye));
  Halves halves;
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      // Camera looks along -z with no rotation: view space is world space about the eye.
      const double ndcX = 2.0 * (x + 0.5) / kWidth - 1.0;
      const double ndcY = 2.0 * (y + 0.5) / kHeight - 1.0;
      const glm::dvec3 dir =
          glm::normalize(glm::dvec3(ndcX / projection[0][0], ndcY / projection[1][1], -1.0));
      const double angle = std::acos(std::min(1.0, glm::dot(dir, centre)));
      const double radial = angle / angularRadius;
      if (radial < 0.2 || radial > 0.7) continue;
      const size_t i = size_t(y) * kWidth + size_t(x);
      (dir.x < 0.0 ? halves.left : halves.right).push_back(i);
    }
  }
  return halves;
}

double meanLuminance(const std::vector<float>& image, const std::vector<size_t>& pixels) {
  double sum = 0.0;
  for (size_t i : pixels) sum += luminance(image, i);
  return pixels.empty() ? 0.0 : sum / double(pixels.size());
}

TEST_F(SampleGlassRefraction, GlassShowsTheWallBehindItFlipped) {
  const std::vector<float> wall = render(Ball::None);
  const std::vector<float> glass = render(Ball::Glass);
  const std::vector<float> opaque = render(Ball::Opaque);
  const size_t n = size_t(kWidth) * kHeight * 4;
  ASSERT_EQ(wall.size(), n);
  ASSERT_EQ(glass.size(), n);
  ASSERT_EQ(opaque.size(), n);
  for (float v : glass) ASSERT_TRUE(std::isfinite(v));

  const Halves halves = ballHalves();
  ASSERT_GT(halves.left.size(), 100u);
  ASSERT_GT(halves.right.size(), 100u);

  // Without the ball: the wall as it is, pale on the left.
  const double wallLeft = meanLuminance(wall, halves.left);
  const double wallRight = meanLuminance(wall, halves.right);
  ASSERT_GT(wallLeft, 4.0 * wallRight) << "the wall itself must read pale | dark";

  // Through the glass: swapped, and about as bright as the wall it shows (little is lost to
  // Fresnel reflection at n = 1.13 and to 1 m of tinted glass).
  const double glassLeft = meanLuminance(glass, halves.left);
  const double glassRight = meanLuminance(glass, halves.right);
  EXPECT_GT(glassRight, 4.0 * glassLeft) << "left " << glassLeft << " right " << glassRight;
  EXPECT_GT(glassRight, 0.4 * wallLeft);
  EXPECT_LT(glassRight, 1.2 * wallLeft);

  // The opaque ball is one grey surface: neither the wall's split nor its swap.
  const double opaqueLeft = meanLuminance(opaque, halves.left);
  const double opaqueRight = meanLuminance(opaque, halves.right);
  EXPECT_LT(std::abs(opaqueLeft - opaqueRight), 0.5 * std::max(opaqueLeft, opaqueRight));
  double differ = 0.0;
  for (const std::vector<size_t>* side : {&halves.left, &halves.right}) {
    for (size_t i : *side) differ += std::abs(luminance(glass, i) - luminance(opaque, i));
  }
  differ /= double(halves.left.size() + halves.right.size());
  std::printf("wall %.4f | %.4f, glass %.4f | %.4f, opaque %.4f | %.4f, glass - opaque %.4f\n",
              wallLeft, wallRight, glassLeft, glassRight, opaqueLeft, opaqueRight, differ);
  EXPECT_GT(differ, 0.25 * wallLeft) << "glass pixels must not be an opaque ball's";
}

// With nothing behind it but open water, the ball shows the water column around it, shafts
// included: what a ray meets at tens of metres is the frame's own background along its
// direction, not a darker stand-in (a weak lens bends the view by a few degrees, and open
// water's light depends on the direction alone).
TEST_F(SampleGlassRefraction, GlassInOpenWaterShowsTheWaterAroundIt) {
  const std::vector<float> water = render(Ball::None, Backdrop::OpenWater, true);
  const std::vector<float> glass = render(Ball::Glass, Backdrop::OpenWater, true);
  ASSERT_EQ(water.size(), glass.size());
  const Halves halves = ballHalves();
  std::vector<size_t> pixels = halves.left;
  pixels.insert(pixels.end(), halves.right.begin(), halves.right.end());
  const double open = meanLuminance(water, pixels), through = meanLuminance(glass, pixels);
  std::printf("open water %.4f, through the glass %.4f\n", open, through);
  ASSERT_GT(open, 0.0);
  EXPECT_GT(through, 0.75 * open);
  EXPECT_LT(through, 1.25 * open);
}

}  // namespace
