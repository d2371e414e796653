#include "seabed_caustics/local_water_layout.h"

#include <algorithm>
#include <cmath>

#include "core/block_check.h"
#include "core/frame_geometry.h"
#include "core/validation.h"
#include "seabed_caustics/wavefront_area_ratio_layout.h"

namespace postfx::detail {
namespace {

// The sizes a region's grid and layers take, from its settings alone (the layout, the shared
// texture and the memory estimate all read these).
int texelsPerSide(const LocalWater& region) {
  return region.gridResolution + 2 * int(std::ceil(kLocalWaterMargin * region.gridResolution));
}
int pointsPerSide(const LocalWater& region) {
  return region.gridResolution + 2;
}
int depthLayers(const LocalWater& region) {
  return std::clamp(region.depthLayers, 1, kMaxWavefrontAreaRatioLayers);
}
int fieldLayers(const LocalWater& region) {
  return depthLayers(region) * (region.mode == LocalWaterMode::Add ? 2 : 1);
}

}  // namespace

LocalWaterLayout localWaterLayout(const LocalWater& region, const FrameDesc& frame) {
  LocalWaterLayout l;
  l.cells = region.gridResolution;
  l.texels = texelsPerSide(region);
  l.pointsPerSide = pointsPerSide(region);
  l.layers = depthLayers(region);
  l.add = region.mode == LocalWaterMode::Add;
  l.fieldLayers = fieldLayers(region);
  l.axisU = glm::dvec2(std::cos(region.rotation), -std::sin(region.rotation));
  const glm::dvec2 axisV(-l.axisU.y, l.axisU.x);
  l.half = 0.5 * region.size;
  l.cell = region.size / double(l.cells);
  // The margin: half of what the texture has beyond the rectangle's cells, on each side.
  l.windowCorner = -l.half - 0.5 * double(l.texels - l.cells) * l.cell;
  const glm::dvec3 sun = glm::normalize(frame.sun.direction);
  const glm::dvec2 sunXz(sun.x, sun.z);
  l.sunLocal = glm::dvec3(glm::dot(sunXz, l.axisU), sun.y, glm::dot(sunXz, axisV));
  const glm::dvec3 down = refractedSunDown(l.sunLocal, frame.water.ior);
  l.drift = glm::dvec2(down.x, down.z) / std::max(-down.y, 1e-6);
  for (int k = 0; k < l.layers; ++k)
    l.depth[k] = wavefrontAreaRatioLayerDepth(k, l.layers, double(region.maxDepth));
  return l;
}

shared::LocalWaterBlock buildLocalWaterBlock(const FrameDesc& frame) {
  shared::LocalWaterBlock b{};
  const WaterSurface& water = frame.water;
  const int count = water.localWater == nullptr ? 0 : water.localWaterCount;
  b.count = glm::vec4(float(count), 0.0f, 0.0f, 0.0f);
  const glm::dvec2 camera(frame.camera.position.x, frame.camera.position.z);
  const LocalWaterTexture texture = localWaterTexture(frame);
  for (int r = 0; r < count; ++r) {
    const LocalWater& region = water.localWater[r];
    const LocalWaterLayout l = localWaterLayout(region, frame);
    const glm::dvec2 centre = region.centre - camera;  // in double: both may be ~1e6 m out
    b.frame[r] = glm::vec4(saturatedFloat(centre.x), saturatedFloat(centre.y), float(l.axisU.x),
                           float(l.axisU.y));
    b.lookup[r] = glm::vec4(float(texture.firstLayer[r]), float(l.texels) / float(texture.side),
                            float(texture.side), 0.0f);
    b.extent[r] =
        glm::vec4(float(l.half.x), float(l.half.y), region.edgeBlend, l.add ? 0.0f : 1.0f);
    const glm::dvec2 window = double(l.texels) * l.cell;
    b.window[r] = glm::vec4(float(l.windowCorner.x), float(l.windowCorner.y), float(1.0 / window.x),
                            float(1.0 / window.y));
    b.drift[r] = glm::vec4(float(l.drift.x), float(l.drift.y), float(l.layers),
                           float(-0.5 * std::log2(l.cell.x * l.cell.y)));
    for (int k = 0; k < l.layers; ++k) b.depths[2 * r + k / 4][k % 4] = float(l.depth[k]);
  }
  return b;
}

LocalWaterTexture localWaterTexture(const FrameDesc& frame) {
  LocalWaterTexture t;
  for (int r = 0; r < frame.water.localWaterCount && frame.water.localWater != nullptr; ++r) {
    const LocalWater& region = frame.water.localWater[r];
    t.side = std::max(t.side, texelsPerSide(region));
    t.firstLayer[r] = t.layers;
    t.layers += fieldLayers(region);
  }
  return t;
}

std::uint64_t localWaterTextureBytes(const LocalWaterTexture& texture) {
  std::uint64_t texelCount = 0;
  for (int level = 0; level < wavefrontAreaRatioMipLevels(texture.side); ++level) {
    const std::uint64_t side = std::uint64_t(std::max(texture.side >> level, 1));
    texelCount += side * side;
  }
  return texelCount * std::uint64_t(texture.layers) * 4;
}

std::uint64_t localWaterGridPoints(const FrameDesc& frame) {
  std::uint64_t points = 0;
  for (int r = 0; r < frame.water.localWaterCount; ++r) {
    const std::uint64_t side = std::uint64_t(pointsPerSide(frame.water.localWater[r]));
    points = std::max(points, side * side);
  }
  return points;
}

std::uint64_t localWaterBytes(const FrameDesc& frame) {
  if (frame.water.localWater == nullptr || frame.water.localWaterCount <= 0) return 0;
  // Two vec4 per grid point (GridPointBuffer).
  return localWaterGridPoints(frame) * 2 * 16 + localWaterTextureBytes(localWaterTexture(frame));
}

}  // namespace postfx::detail
