#include "local_water_readback.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>

namespace ocean::reference {
namespace {

constexpr double kMaxSlope = 64.0;  // postfx shared CAUSTICS_MAX_SLOPE
constexpr double kMaxHeight = 1e3;  // postfx shared CAUSTICS_MAX_HEIGHT

double finiteOrZero(double value) {
  return std::isfinite(value) ? value : 0.0;
}

double sanitize(double value, double limit) {
  return std::abs(value) <= limit ? value : 0.0;
}

}  // namespace

glm::dvec3 LocalWaterSurface::Region::at(glm::dvec2 uv) const {
  const double x = uv.x * width - 0.5, y = uv.y * height - 0.5;
  const double fx = std::floor(x), fy = std::floor(y);
  const double ax = x - fx, ay = y - fy;
  auto clampTo = [](double i, int n) { return std::clamp(static_cast<int>(i), 0, n - 1); };
  const int x0 = clampTo(fx, width), x1 = clampTo(fx + 1.0, width);
  const int y0 = clampTo(fy, height), y1 = clampTo(fy + 1.0, height);
  auto t = [&](int i, int j) { return texels[static_cast<std::size_t>(j) * width + i]; };
  return (1.0 - ay) * ((1.0 - ax) * t(x0, y0) + ax * t(x1, y0)) +
         ay * ((1.0 - ax) * t(x0, y1) + ax * t(x1, y1));
}

bool LocalWaterSurface::read(const postfx::WaterSurface& water, const Surface& beneath,
                             std::string& error) {
  beneath_ = &beneath;
  regions_.clear();
  maxHeight_ = beneath.maxHeight();
  maxSlope_ = beneath.maxSlope();
  featureSize_ = beneath.featureSize();
  double regionHeight = 0.0, regionSlope = 0.0;
  for (int r = 0; r < water.localWaterCount && water.localWater != nullptr; ++r) {
    const postfx::LocalWater& desc = water.localWater[r];
    const GLuint texture = desc.texture.texture;
    GLint target = 0;
    if (texture == 0 || glIsTexture(texture) != GL_TRUE ||
        (glGetTextureParameteriv(texture, GL_TEXTURE_TARGET, &target), target != GL_TEXTURE_2D)) {
      error = "local water " + std::to_string(r) + ": texture " + std::to_string(texture) +
              " is not a GL_TEXTURE_2D";
      return false;
    }
    Region region;
    region.centre = desc.centre;
    region.half = 0.5 * desc.size;
    region.axisU = glm::dvec2(std::cos(desc.rotation), -std::sin(desc.rotation));
    region.replace = desc.mode == postfx::LocalWaterMode::Replace;
    glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_WIDTH, &region.width);
    glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_HEIGHT, &region.height);
    std::vector<glm::vec4> rgba(static_cast<std::size_t>(region.width) * region.height);
    glGetTextureImage(texture, 0, GL_RGBA, GL_FLOAT,
                      static_cast<GLsizei>(rgba.size() * sizeof(glm::vec4)), rgba.data());
    region.texels.resize(rgba.size());
    for (std::size_t i = 0; i < rgba.size(); ++i) {
      const glm::dvec3 t(finiteOrZero(rgba[i].x), finiteOrZero(rgba[i].y), finiteOrZero(rgba[i].z));
      region.texels[i] = t;
      regionHeight = std::max(regionHeight, std::abs(t.z));
      regionSlope = std::max(regionSlope, std::hypot(t.x, t.y));
    }
    featureSize_ =
        std::min({featureSize_, desc.size.x / region.width, desc.size.y / region.height});
    regions_.push_back(std::move(region));
  }
  // A point may lie in several regions (each adds or replaces in turn): the bounds add up.
  const double regions = static_cast<double>(regions_.size());
  maxHeight_ = std::min(maxHeight_ + regions * regionHeight, kMaxHeight);
  maxSlope_ = std::min(maxSlope_ + regions * regionSlope, kMaxSlope * std::sqrt(2.0));
  return true;
}

SurfaceSample LocalWaterSurface::sample(double x, double z) const {
  SurfaceSample s = beneath_->sample(x, z);
  for (const Region& r : regions_) {
    const glm::dvec2 d = glm::dvec2(x, z) - r.centre;
    const glm::dvec2 axisV(-r.axisU.y, r.axisU.x);
    const glm::dvec2 local(glm::dot(d, r.axisU), glm::dot(d, axisV));
    if (std::abs(local.x) > r.half.x || std::abs(local.y) > r.half.y) continue;
    const glm::dvec3 t = r.at(local / (2.0 * r.half) + 0.5);
    // The gradient from the region's axes into world x, z.
    const glm::dvec2 slope = t.x * r.axisU + t.y * axisV;
    if (r.replace) s = SurfaceSample{};
    s.height = sanitize(s.height + t.z, kMaxHeight);
    s.slopeX = sanitize(s.slopeX + slope.x, kMaxSlope);
    s.slopeZ = sanitize(s.slopeZ + slope.y, kMaxSlope);
  }
  return s;
}

}  // namespace ocean::reference
