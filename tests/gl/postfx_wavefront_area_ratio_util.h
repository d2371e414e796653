#pragma once
// Helpers for the wavefront area ratio GL tests: a frame in that model, the
// irradiance read back, and box averages of it over the CPU reference's bins.
#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <postfx/postfx.h>
#include <postfx/testing.h>
#include <postfx/water/ocean.h>

#include "postfx_scene.h"
#include "seabed_reference.h"

namespace postfxtest {

inline constexpr postfx::Feature kPhysical = postfx::Feature::Caustics |
                                             postfx::testing::RawCausticOutput |
                                             postfx::Feature::WavefrontAreaRatio;

// Camera 2 m under the level, looking down at a floor `floorDepth` m below it; camera xz at
// the centre of a 16 m window whose snapped corner is the world origin for every grid size.
inline SceneSpec wavefrontAreaRatioScene(double floorDepth, int width = 96, int height = 64) {
  SceneSpec s;
  s.width = width;
  s.height = height;
  s.camera = {8.0, -2.0, 8.0};
  s.lookDirection = {0.0, -1.0, -0.2};
  s.floorY = -floorDepth;  // floorY2 unused: stepX stays at its default (no step)
  s.sphere = false;
  return s;
}

inline void useWavefrontAreaRatio(postfx::FrameDesc& frame, int grid, int layers, float maxDepth,
                                  float maxIrradiance = 1e4f) {
  frame.caustics.model = postfx::CausticsModel::WavefrontAreaRatio;
  frame.caustics.gridResolution = grid;
  frame.caustics.windowSize = 16.0f;
  frame.caustics.depthLayers = layers;
  frame.caustics.maxReceiverDepth = maxDepth;
  frame.caustics.maxIrradiance = maxIrradiance;
  frame.caustics.surfaceFadeDepth = 0.0f;
}

// All layers, texel (i, j) of layer k at (k * N + j) * N + i.
inline std::vector<float> readIrradiance(const postfx::testing::CausticIrradianceInfo& info) {
  std::vector<float> texels(static_cast<size_t>(info.resolution) * info.resolution * info.layers);
  glGetTextureImage(info.texture, 0, GL_RED, GL_FLOAT, static_cast<GLsizei>(texels.size() * 4),
                    texels.data());
  return texels;
}

// Mean of layer `layer` over each bin of `bins` (bins must cover whole texels).
inline std::vector<double> binAverage(const postfx::testing::CausticIrradianceInfo& info,
                                      const std::vector<float>& texels, int layer,
                                      const ocean::reference::BinGrid& bins) {
  const double texel = info.windowSize / info.resolution;
  const int perBin = static_cast<int>(std::lround(bins.binSize / texel));
  const int i0 = static_cast<int>(std::lround((bins.origin.x - info.windowOrigin.x) / texel));
  const int j0 = static_cast<int>(std::lround((bins.origin.y - info.windowOrigin.y) / texel));
  std::vector<double> out(static_cast<size_t>(bins.countX) * bins.countZ, 0.0);
  const size_t base = static_cast<size_t>(layer) * info.resolution * info.resolution;
  for (int bj = 0; bj < bins.countZ; ++bj)
    for (int bi = 0; bi < bins.countX; ++bi) {
      double sum = 0.0;
      for (int j = 0; j < perBin; ++j)
        for (int i = 0; i < perBin; ++i) {
          const int x = i0 + bi * perBin + i, y = j0 + bj * perBin + j;
          sum += static_cast<double>(texels[base + static_cast<size_t>(y) * info.resolution + x]);
        }
      out[static_cast<size_t>(bj) * bins.countX + bi] = sum / (perBin * perBin);
    }
  return out;
}

// Layer `layer` sampled as the caustics pass samples it: bilinear between texel centres,
// clamped to the edge, at world (x, z).
inline double sampleLayer(const postfx::testing::CausticIrradianceInfo& info,
                          const std::vector<float>& texels, int layer, double x, double z) {
  const int n = info.resolution;
  const double u = (x - info.windowOrigin.x) / info.windowSize * n - 0.5;
  const double v = (z - info.windowOrigin.y) / info.windowSize * n - 0.5;
  const double fu = std::floor(u), fv = std::floor(v), a = u - fu, b = v - fv;
  auto at = [&](double i, double j) {
    const int ci = std::clamp(static_cast<int>(i), 0, n - 1);
    const int cj = std::clamp(static_cast<int>(j), 0, n - 1);
    return static_cast<double>(
        texels[(static_cast<size_t>(layer) * n + static_cast<size_t>(cj)) * n + ci]);
  };
  return at(fu, fv) * (1 - a) * (1 - b) + at(fu + 1, fv) * a * (1 - b) +
         at(fu, fv + 1) * (1 - a) * b + at(fu + 1, fv + 1) * a * b;
}

// sqrt(mean((a - ref)^2)) / mean(ref).
inline double relativeRmse(const std::vector<double>& a, const std::vector<double>& ref) {
  double se = 0.0, mean = 0.0;
  for (size_t i = 0; i < ref.size(); ++i) {
    se += (a[i] - ref[i]) * (a[i] - ref[i]);
    mean += ref[i];
  }
  mean /= static_cast<double>(ref.size());
  return std::sqrt(se / static_cast<double>(ref.size())) / mean;
}

inline double mean(const std::vector<double>& v) {
  double s = 0.0;
  for (double x : v) s += x;
  return s / static_cast<double>(v.size());
}

// A small real sea: 64^2 texels, the default three cascades (250, 37, 5.3 m), 7 m/s wind.
inline std::unique_ptr<postfx::water::Ocean> makeSmallOcean(double timeSeconds) {
  postfx::water::OceanDesc desc;
  desc.resolution = 64;
  desc.windSpeed = 7.0;
  std::unique_ptr<postfx::water::Ocean> ocean;
  std::string error;
  if (postfx::water::Ocean::create(desc, ocean, error) != postfx::water::Result::Ok) return nullptr;
  if (ocean->update(timeSeconds, error) != postfx::water::Result::Ok) return nullptr;
  return ocean;
}

inline void useOcean(postfx::FrameDesc& frame, const postfx::water::Ocean& ocean) {
  frame.water.texture = {ocean.slopeTexture(), GL_RGBA16F};
  frame.water.cascadeCount = ocean.cascadeCount();
  for (int c = 0; c < ocean.cascadeCount(); ++c) frame.water.tileSize[c] = ocean.tileSize(c);
  frame.water.origin = glm::dvec2(0.0);
  frame.water.level = 0.0;
}

// The frame both flat-seabed comparisons with traced light use (report/caustic_rows.h): the
// ocean's water at level 0, the sun `elevationDegrees` up at 30 degrees azimuth, the camera 1 m
// under the level above (8, 8) (flatSeabedView: the sun and camera alone, for any water).
inline void flatSeabedView(postfx::FrameDesc& frame, double elevationDegrees) {
  const double e = glm::radians(elevationDegrees), azimuth = glm::radians(30.0);
  frame.sun.direction = {std::cos(e) * std::cos(azimuth), std::sin(e),
                         std::cos(e) * std::sin(azimuth)};
  frame.camera.position = {8.0, -1.0, 8.0};
}
inline postfx::FrameDesc flatSeabedFrame(const postfx::water::Ocean& ocean,
                                         double elevationDegrees) {
  postfx::FrameDesc frame;
  useOcean(frame, ocean);
  flatSeabedView(frame, elevationDegrees);
  return frame;
}

}  // namespace postfxtest
