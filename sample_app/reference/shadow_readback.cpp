#include "shadow_readback.h"

#include <algorithm>
#include <cmath>

namespace ocean::reference {

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

}  // namespace ocean::reference
