#include "godray_water.h"

#include <algorithm>
#include <cmath>

namespace reference {
namespace {

int wrap(int i, int n) {
  const int r = i % n;
  return r < 0 ? r + n : r;
}

}  // namespace

WaterSlopes WaterSlopes::readBack(GLuint texture, int cascades, bool single2D) {
  WaterSlopes out;
  GLint levels = 1;
  glGetTextureParameteriv(texture, GL_TEXTURE_IMMUTABLE_LEVELS, &levels);
  GLint immutable = 0;
  glGetTextureParameteriv(texture, GL_TEXTURE_IMMUTABLE_FORMAT, &immutable);
  if (!immutable) {
    // A mutable texture: count the levels that have storage.
    levels = 0;
    for (GLint w = 1; w > 0 && levels < 32; ++levels)
      glGetTextureLevelParameteriv(texture, levels, GL_TEXTURE_WIDTH, &w);
    levels = std::max(levels - 1, 1);
  }
  out.layers_.assign(static_cast<size_t>(cascades), {});
  for (int level = 0; level < levels; ++level) {
    GLint w = 0, h = 0, d = 1;
    glGetTextureLevelParameteriv(texture, level, GL_TEXTURE_WIDTH, &w);
    glGetTextureLevelParameteriv(texture, level, GL_TEXTURE_HEIGHT, &h);
    if (!single2D) glGetTextureLevelParameteriv(texture, level, GL_TEXTURE_DEPTH, &d);
    std::vector<glm::vec2> texels(static_cast<size_t>(w) * h * d);
    glGetTextureImage(texture, level, GL_RG, GL_FLOAT,
                      static_cast<GLsizei>(texels.size() * sizeof(glm::vec2)), texels.data());
    for (int c = 0; c < cascades && c < d; ++c) {
      Level l;
      l.width = w;
      l.height = h;
      const size_t perLayer = static_cast<size_t>(w) * h;
      l.texels.assign(texels.begin() + static_cast<std::ptrdiff_t>(c * perLayer),
                      texels.begin() + static_cast<std::ptrdiff_t>((c + 1) * perLayer));
      out.layers_[static_cast<size_t>(c)].push_back(std::move(l));
    }
  }
  return out;
}

glm::dvec2 WaterSlopes::bilinear(const Level& level, glm::dvec2 uv) const {
  // Texel centres at (i + 0.5) / n, GL_REPEAT.
  const double x = uv.x * level.width - 0.5, y = uv.y * level.height - 0.5;
  const double fx = std::floor(x), fy = std::floor(y);
  const double ax = x - fx, ay = y - fy;
  const int x0 = wrap(static_cast<int>(std::fmod(fx, level.width)), level.width);
  const int y0 = wrap(static_cast<int>(std::fmod(fy, level.height)), level.height);
  const int x1 = wrap(x0 + 1, level.width), y1 = wrap(y0 + 1, level.height);
  auto at = [&](int i, int j) { return level.texels[static_cast<size_t>(j) * level.width + i]; };
  return (1.0 - ay) * ((1.0 - ax) * at(x0, y0) + ax * at(x1, y0)) +
         ay * ((1.0 - ax) * at(x0, y1) + ax * at(x1, y1));
}

glm::dvec2 WaterSlopes::sample(int cascade, glm::dvec2 uv, double lod) const {
  const std::vector<Level>& chain = layers_[static_cast<size_t>(cascade)];
  const int last = static_cast<int>(chain.size()) - 1;
  if (last == 0 || !(lod > 0.0)) return bilinear(chain[0], uv);  // magnification / no mips
  const double clamped = std::min(lod, static_cast<double>(last));
  const int d1 = static_cast<int>(std::floor(clamped));
  const int d2 = std::min(d1 + 1, last);
  const double f = clamped - d1;
  const glm::dvec2 a = bilinear(chain[static_cast<size_t>(d1)], uv);
  if (f <= 0.0 || d2 == d1) return a;
  return (1.0 - f) * a + f * bilinear(chain[static_cast<size_t>(d2)], uv);
}

ShadowDepth ShadowDepth::readBack(GLuint texture) {
  ShadowDepth out;
  if (texture == 0) return out;
  glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_WIDTH, &out.width_);
  glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_HEIGHT, &out.height_);
  out.texels_.resize(static_cast<size_t>(out.width_) * out.height_);
  glGetTextureImage(texture, 0, GL_DEPTH_COMPONENT, GL_FLOAT,
                    static_cast<GLsizei>(out.texels_.size() * sizeof(float)), out.texels_.data());
  return out;
}

double ShadowDepth::visibility(glm::dvec2 uv, double ref, bool reverseZ) const {
  const double x = uv.x * width_ - 0.5, y = uv.y * height_ - 0.5;
  const double fx = std::floor(x), fy = std::floor(y);
  const double ax = x - fx, ay = y - fy;
  auto lit = [&](double i, double j) {
    const int xi = static_cast<int>(std::clamp(i, 0.0, double(width_ - 1)));
    const int yi = static_cast<int>(std::clamp(j, 0.0, double(height_ - 1)));
    const double texel = texels_[static_cast<size_t>(yi) * width_ + xi];
    return (reverseZ ? ref >= texel : ref <= texel) ? 1.0 : 0.0;
  };
  return (1.0 - ay) * ((1.0 - ax) * lit(fx, fy) + ax * lit(fx + 1, fy)) +
         ay * ((1.0 - ax) * lit(fx, fy + 1) + ax * lit(fx + 1, fy + 1));
}

}  // namespace reference
