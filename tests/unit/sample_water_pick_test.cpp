// The view's click on the water (sample_app/src/water_pick.h): the ray through a pixel meets the
// water's plane where the camera's own projection puts that point.
#include <gtest/gtest.h>

#include <cmath>

#include "camera.h"
#include "water_pick.h"

namespace {

TEST(WaterPick, TheCentreRayMeetsThePlaneAlongTheView) {
  ocean::Preset pool;
  std::string known;
  ASSERT_TRUE(ocean::findPreset("pool", pool, known)) << known;
  const ocean::Camera& camera = pool.camera;
  glm::dvec2 xz;
  ASSERT_TRUE(ocean::pickWaterPlane(camera, 16.0 / 9.0, {0.0, 0.0}, 0.0, xz));
  const glm::dvec3 f = camera.forward();
  const double t = -camera.position.y / f.y;
  EXPECT_NEAR(xz.x, camera.position.x + t * f.x, 1e-9);
  EXPECT_NEAR(xz.y, camera.position.z + t * f.z, 1e-9);
}

// A point on the plane, projected by the camera's own matrices to NDC, picks back to itself.
TEST(WaterPick, PicksBackWhatTheProjectionShows) {
  ocean::Preset pool;
  std::string known;
  ASSERT_TRUE(ocean::findPreset("pool", pool, known));
  const ocean::Camera& camera = pool.camera;
  const double aspect = 1.5;
  const glm::dmat4 viewProjection =
      camera.projection(aspect) * glm::dmat4(glm::transpose(camera.rotation()));
  for (const glm::dvec2 point : {glm::dvec2(1.3, -2.1), glm::dvec2(-3.0, 3.5)}) {
    const glm::dvec4 clip =
        viewProjection * glm::dvec4(glm::dvec3(point.x, 0.2, point.y) - camera.position, 1.0);
    const glm::dvec2 ndc = glm::dvec2(clip) / clip.w;
    glm::dvec2 xz;
    ASSERT_TRUE(ocean::pickWaterPlane(camera, aspect, ndc, 0.2, xz));
    EXPECT_NEAR(xz.x, point.x, 1e-6);
    EXPECT_NEAR(xz.y, point.y, 1e-6);
  }
}

TEST(WaterPick, MissesAboveTheHorizonAndWhenParallel) {
  ocean::Camera camera;
  camera.position = {0.0, 2.0, 0.0};
  camera.pitch = 0.0;
  glm::dvec2 xz;
  EXPECT_FALSE(ocean::pickWaterPlane(camera, 1.0, {0.0, 0.5}, 0.0, xz));  // up: away from it
  EXPECT_FALSE(ocean::pickWaterPlane(camera, 1.0, {0.0, 0.0}, 0.0, xz));  // level: parallel
  EXPECT_TRUE(ocean::pickWaterPlane(camera, 1.0, {0.0, -0.5}, 0.0, xz));
  camera.position.y = -2.0;  // from below the surface a ray upward meets it
  EXPECT_TRUE(ocean::pickWaterPlane(camera, 1.0, {0.0, 0.5}, 0.0, xz));
}

}  // namespace
