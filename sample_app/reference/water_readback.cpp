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

}  // namespace

bool WaterTextureSurface::read(const postfx::WaterSurface& water, std::string& error) {
  const GLuint texture = water.texture.texture;
  if (texture == 0 || glIsTexture(texture) != GL_TRUE) {
    error = "water texture " + std::to_string(texture) + " is not a texture";
    return false;
  }
  GLint target = 0, width = 0, height = 0, layers = 1;
  glGetTextureParameteriv(texture, GL_TEXTURE_TARGET, &target);
  glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_WIDTH, &width);
  glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_HEIGHT, &height);
  if (target == GL_TEXTURE_2D_ARRAY) {
    glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_DEPTH, &layers);
  } else if (target != GL_TEXTURE_2D) {
    error = "water texture must be GL_TEXTURE_2D_ARRAY or GL_TEXTURE_2D";
    return false;
  }
  if (width <= 0 || width != height || water.cascadeCount < 1 ||
      water.cascadeCount > std::min<int>(layers, postfx::kMaxCascades)) {
    error = "water texture must be square with at least cascadeCount layers";
    return false;
  }
  size_ = width;
  cascadeCount_ = water.cascadeCount;
  origin_ = water.origin;
  const size_t perLayer = static_cast<size_t>(width) * static_cast<size_t>(height);
  std::vector<float> rgba(perLayer * 4 * static_cast<size_t>(layers));
  glGetTextureImage(texture, 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(rgba.size() * 4),
                    rgba.data());
  texels_.assign(perLayer * static_cast<size_t>(cascadeCount_), Texel{});
  maxHeight_ = maxSlope_ = 0.0;
  featureSize_ = 1e300;
  for (int c = 0; c < cascadeCount_; ++c) {
    tileSize_[c] = water.tileSize[c];
    featureSize_ = std::min(featureSize_, tileSize_[c] / size_);
    double layerHeight = 0.0, layerSlope = 0.0;
    for (size_t i = 0; i < perLayer; ++i) {
      const float* p = &rgba[(static_cast<size_t>(c) * perLayer + i) * 4];
      Texel& t = texels_[static_cast<size_t>(c) * perLayer + i];
      // NaN/Inf stay: they spoil the bilinear sum, which is then sanitised as on the GPU.
      t = {p[0], p[1], p[2]};
      layerHeight = std::max(layerHeight, std::abs(finiteOrZero(t.height)));
      layerSlope = std::max(layerSlope, std::hypot(finiteOrZero(t.slopeX), finiteOrZero(t.slopeZ)));
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
  double sx = 0.0, sz = 0.0, h = 0.0;
  const size_t perLayer = static_cast<size_t>(size_) * static_cast<size_t>(size_);
  for (int c = 0; c < cascadeCount_; ++c) {
    // Texel space: centres at integers after the half-texel shift.
    const double tu = (x - origin_.x) / tileSize_[c] * size_ - 0.5;
    const double tv = (z - origin_.y) / tileSize_[c] * size_ - 0.5;
    const double fu = std::floor(tu), fv = std::floor(tv);
    const double au = tu - fu, av = tv - fv;
    auto wrap = [this](double i) {
      const long n = size_;
      const long k = static_cast<long>(std::fmod(i, static_cast<double>(n)));
      return static_cast<size_t>(k < 0 ? k + n : k);
    };
    const size_t u0 = wrap(fu), u1 = wrap(fu + 1.0), v0 = wrap(fv), v1 = wrap(fv + 1.0);
    const Texel* layer = &texels_[static_cast<size_t>(c) * perLayer];
    const Texel& t00 = layer[v0 * size_ + u0];
    const Texel& t10 = layer[v0 * size_ + u1];
    const Texel& t01 = layer[v1 * size_ + u0];
    const Texel& t11 = layer[v1 * size_ + u1];
    const double w00 = (1 - au) * (1 - av), w10 = au * (1 - av), w01 = (1 - au) * av, w11 = au * av;
    sx += w00 * t00.slopeX + w10 * t10.slopeX + w01 * t01.slopeX + w11 * t11.slopeX;
    sz += w00 * t00.slopeZ + w10 * t10.slopeZ + w01 * t01.slopeZ + w11 * t11.slopeZ;
    h += w00 * t00.height + w10 * t10.height + w01 * t01.height + w11 * t11.height;
  }
  return {sanitize(h, kMaxHeight), sanitize(sx, kMaxSlope), sanitize(sz, kMaxSlope)};
}

}  // namespace ocean::reference
