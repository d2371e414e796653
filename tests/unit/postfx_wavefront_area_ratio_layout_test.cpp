// Where the physical caustics model puts its window, grids and depth layers (irradiance_layout):
// snapped in world space so the pattern does not swim, covering what it must, far from the
// origin as near it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/frame_geometry.h"
#include "core/shared_math.h"
#include "seabed_caustics/wavefront_area_ratio_layout.h"

namespace {

using postfx::detail::wavefrontAreaRatioLayout;
using postfx::detail::WavefrontAreaRatioLayout;

postfx::FrameDesc physicalFrame(const glm::dvec3& camera) {
  postfx::FrameDesc f;
  f.camera.position = camera;
  f.sun.direction = glm::normalize(glm::dvec3(0.3, 1.0, 0.2));
  f.caustics.model = postfx::CausticsModel::WavefrontAreaRatio;
  f.caustics.gridResolution = 256;
  f.caustics.windowSize = 32.0f;
  f.caustics.depthLayers = 4;
  f.caustics.maxReceiverDepth = 16.0f;
  return f;
}

bool isMultiple(double value, double step) {
  const double k = value / step;
  return std::abs(k - std::round(k)) < 1e-6;
}

TEST(WavefrontAreaRatioLayout, LayerDepthsAreQuadraticUpToTheMaximum) {
  const WavefrontAreaRatioLayout l = wavefrontAreaRatioLayout(physicalFrame(glm::dvec3(0.0)));
  ASSERT_EQ(l.layers, 4);
  const double expected[] = {1.0, 4.0, 9.0, 16.0};
  for (int k = 0; k < 4; ++k) EXPECT_DOUBLE_EQ(l.depth[k], expected[k]);
}

TEST(WavefrontAreaRatioLayout, WindowAndGridsAreSnappedInWorldSpace) {
  for (const glm::dvec3 camera :
       {glm::dvec3(3.3, -2.0, 7.1), glm::dvec3(1e6 + 0.37, -5.0, -1e6 - 0.91)}) {
    const WavefrontAreaRatioLayout a = wavefrontAreaRatioLayout(physicalFrame(camera));
    // The window snaps to texels of the coarsest mip level the lookup filters with, so that
    // every level stays on one world grid as the camera moves.
    const double snap = a.texel * double(1 << postfx::shared::IRRADIANCE_MIP_LEVELS);
    EXPECT_TRUE(isMultiple(a.windowOrigin.x, snap) && isMultiple(a.windowOrigin.y, snap));
    // The camera stays inside the window's central snap step.
    EXPECT_LE(std::abs(a.windowOrigin.x + 0.5 * a.windowSize - camera.x), snap);
    for (int k = 0; k < a.layers; ++k)
      EXPECT_TRUE(isMultiple(a.gridOrigin[k].x, a.cell) && isMultiple(a.gridOrigin[k].y, a.cell));
    // A move within the step changes nothing; 10 whole steps move everything by exactly that.
    const glm::dvec3 small = camera + glm::dvec3(0.3 * snap, 0.0, -0.2 * snap);
    const glm::dvec3 whole = camera + glm::dvec3(10.0 * snap, 0.0, 0.0);
    const WavefrontAreaRatioLayout b = wavefrontAreaRatioLayout(physicalFrame(small));
    const WavefrontAreaRatioLayout c = wavefrontAreaRatioLayout(physicalFrame(whole));
    const double sameInStep = std::abs(b.windowOrigin.x - a.windowOrigin.x) +
                              std::abs(b.windowOrigin.y - a.windowOrigin.y);
    const double step = (c.windowOrigin.x - a.windowOrigin.x) / snap;
    std::printf(
        "camera (%.2f, %.2f): window corner moves %.3g m for a 0.3-step move, %.6f "
        "steps for a 10-step move\n",
        camera.x, camera.z, sameInStep, step);
    const bool insideOneStep =
        std::floor((camera.x - 16.0) / snap) == std::floor((small.x - 16.0) / snap) &&
        std::floor((camera.z - 16.0) / snap) == std::floor((small.z - 16.0) / snap);
    if (insideOneStep) {
      EXPECT_EQ(sameInStep, 0.0);
    }
    EXPECT_NEAR(step, 10.0, 1e-6);
  }
}

// Light reaching the window from a layer's depth entered the surface over the window moved
// toward the sun by the flat-water drift; the grid must cover that with the margin around it.
TEST(WavefrontAreaRatioLayout, GridsCoverTheWindowsSourceOnTheSurface) {
  const postfx::FrameDesc f = physicalFrame(glm::dvec3(5.0, -3.0, 5.0));
  const WavefrontAreaRatioLayout l = wavefrontAreaRatioLayout(f);
  const glm::dvec3 down = postfx::detail::refractedSunDown(f.sun.direction, f.water.ior);
  const glm::dvec2 drift = glm::dvec2(down.x, down.z) / -down.y;
  const double margin = postfx::detail::kGridMargin * l.windowSize;
  for (int k = 0; k < l.layers; ++k) {
    const glm::dvec2 sourceMin = l.windowOrigin - drift * l.depth[k] - margin;
    const glm::dvec2 sourceMax = sourceMin + l.windowSize + 2.0 * margin;
    const glm::dvec2 gridMax = l.gridOrigin[k] + l.cell * static_cast<double>(l.cells);
    EXPECT_LE(l.gridOrigin[k].x, sourceMin.x + 1e-9);
    EXPECT_LE(l.gridOrigin[k].y, sourceMin.y + 1e-9);
    EXPECT_GE(gridMax.x, sourceMax.x - 1e-9);
    EXPECT_GE(gridMax.y, sourceMax.y - 1e-9);
  }
}

}  // namespace
