#include "water_readback.h"

#include <algorithm>
#include <cmath>

namespace ocean::reference {
namespace {

constexpr double kMaxSlope = 64.0;  // postfx shared CAUSTICS_MAX_SLOPE
constexpr double kMaxHeight = 1e3;  // postfx shared CAUSTICS_MAX_HEIGHT

double sanitize(double value, double limit) {
  return std::abs(value) <= limit ? value : 0.0;
}

double finiteOrZero(double value) {
  return std::isfinite(value) ? value : 0.0;
}

int wrap(double i, int n) {
  const int r = static_cast<int>(std::fmod(i, static_cast<double>(n)));
  return r < 0 ? r + n : r;
}

// Levels that have storage: all of an immutable texture's, else up to the first empty one.
GLint storedLevels(GLuint texture) {
  GLint immutable = 0, levels = 1;
  glGetTextureParameteriv(texture, GL_TEXTURE_IMMUTABLE_FORMAT, &immutable);
  if (immutable) {
    glGetTextureParameteriv(texture, GL_TEXTURE_IMMUTABLE_LEVELS, &levels);
    return std::max(levels, 1);
  }
  for (levels = 0; levels < 32; ++levels) {
    GLint w = 0;
    glGetTextureLevelParameteriv(texture, levels, GL_TEXTURE_WIDTH, &w);
    if (w <= 0) break;
  }
  return std::max(levels, 1);
}

}  // namespace

bool WaterTextureCopy::read(GLuint texture, int cascades, std::string& error) {
  layers_.clear();
  if (texture == 0 || glIsTexture(texture) != GL_TRUE) {
    error = "water texture " + std::to_string(texture) + " is not a texture";
    return false;
  }
  GLint target = 0, layers = 1;
  glGetTextureParameteriv(texture, GL_TEXTURE_TARGET, &target);
  if (target == GL_TEXTURE_2D_ARRAY) {
    glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_DEPTH, &layers);
  } else if (target != GL_TEXTURE_2D) {
    error = "water texture must be GL_TEXTURE_2D_ARRAY or GL_TEXTURE_2D";
    return false;
  }
  if (cascades < 1 || cascades > layers) {
    error = "water texture has " + std::to_string(layers) + " layers, " + std::to_string(cascades) +
            " cascades asked for";
    return false;
  }
  layers_.assign(static_cast<size_t>(cascades), {});
  const GLint levels = storedLevels(texture);
  for (int level = 0; level < levels; ++level) {
    GLint w = 0, h = 0;
    glGetTextureLevelParameteriv(texture, level, GL_TEXTURE_WIDTH, &w);
    glGetTextureLevelParameteriv(texture, level, GL_TEXTURE_HEIGHT, &h);
    const size_t perLayer = static_cast<size_t>(w) * static_cast<size_t>(h);
    std::vector<glm::vec4> rgba(perLayer * static_cast<size_t>(layers));
    glGetTextureImage(texture, level, GL_RGBA, GL_FLOAT,
                      static_cast<GLsizei>(rgba.size() * sizeof(glm::vec4)), rgba.data());
    for (int c = 0; c < cascades; ++c) {
      Level l{w, h, std::vector<glm::dvec3>(perLayer)};
      for (size_t i = 0; i < perLayer; ++i)
        l.texels[i] = glm::dvec3(rgba[static_cast<size_t>(c) * perLayer + i]);
      layers_[static_cast<size_t>(c)].push_back(std::move(l));
    }
  }
  return true;
}

glm::dvec3 WaterTextureCopy::bilinear(int cascade, int level, glm::dvec2 uv) const {
  const Level& l = layers_[static_cast<size_t>(cascade)][static_cast<size_t>(level)];
  // Texel space: centres at integers after the half-texel shift.
  const double x = uv.x * l.width - 0.5, y = uv.y * l.height - 0.5;
  const double fx = std::floor(x), fy = std::floor(y);
  const double ax = x - fx, ay = y - fy;
  const int x0 = wrap(fx, l.width), y0 = wrap(fy, l.height);
  const int x1 = wrap(x0 + 1.0, l.width), y1 = wrap(y0 + 1.0, l.height);
  auto at = [&](int i, int j) { return texel(cascade, level, i, j); };
  return (1.0 - ay) * ((1.0 - ax) * at(x0, y0) + ax * at(x1, y0)) +
         ay * ((1.0 - ax) * at(x0, y1) + ax * at(x1, y1));
}

glm::dvec3 WaterTextureCopy::sample(int cascade, glm::dvec2 uv, double lod) const {
  const int last = levels() - 1;
  if (last == 0 || !(lod > 0.0)) return bilinear(cascade, 0, uv);  // magnification / no mips
  const double clamped = std::min(lod, static_cast<double>(last));
  const int d1 = static_cast<int>(std::floor(clamped));
  const int d2 = std::min(d1 + 1, last);
  const double f = clamped - d1;
  const glm::dvec3 a = bilinear(cascade, d1, uv);
  if (f <= 0.0 || d2 == d1) return a;
  return (1.0 - f) * a + f * bilinear(cascade, d2, uv);
}

bool WaterTextureSurface::read(const postfx::WaterSurface& water, std::string& error) {
  if (!water_.read(water.texture.texture, water.cascadeCount, error)) return false;
  if (water_.width() != water_.height() || water.cascadeCount > postfx::kMaxCascades) {
    error = "water texture must be square with at most kMaxCascades cascades";
    return false;
  }
  origin_ = water.origin;
  maxHeight_ = maxSlope_ = 0.0;
  featureSize_ = 1e300;
  const int n = water_.width();
  for (int c = 0; c < water.cascadeCount; ++c) {
    tileSize_[c] = water.tileSize[c];
    featureSize_ = std::min(featureSize_, tileSize_[c] / n);
    double layerHeight = 0.0, layerSlope = 0.0;
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) {
        const glm::dvec3& t = water_.texel(c, 0, i, j);
        layerHeight = std::max(layerHeight, std::abs(finiteOrZero(t.z)));
        layerSlope = std::max(layerSlope, std::hypot(finiteOrZero(t.x), finiteOrZero(t.y)));
      }
    }
    // A bilinear mix never exceeds its texels, so per-cascade maxima bound the sum.
    maxHeight_ += layerHeight;
    maxSlope_ += layerSlope;
  }
  maxHeight_ = std::min(maxHeight_, kMaxHeight);
  maxSlope_ = std::min(maxSlope_, kMaxSlope * std::sqrt(2.0));
  return true;
}

SurfaceSample WaterTextureSurface::sample(double x, double z) const {
  // NaN/Inf texels spoil the sum, which is then sanitised as on the GPU.
  glm::dvec3 sum(0.0);
  for (int c = 0; c < water_.cascades(); ++c)
    sum += water_.bilinear(c, 0, (glm::dvec2(x, z) - origin_) / tileSize_[c]);
  return {sanitize(sum.z, kMaxHeight), sanitize(sum.x, kMaxSlope), sanitize(sum.y, kMaxSlope)};
}

}  // namespace ocean::reference
