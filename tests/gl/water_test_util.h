#pragma once
// Helpers for the water GL tests: readback of the contract textures and a small OceanDesc.
#include <epoxy/gl.h>

#include <cmath>
#include <vector>

#include <glm/glm.hpp>

#include <postfx/water/ocean.h>

namespace watertest {

// A small sea for tests: 64^2, the default three cascades.
inline postfx::water::OceanDesc smallDesc(int resolution = 64) {
  postfx::water::OceanDesc desc;
  desc.resolution = resolution;
  return desc;
}

// All layers of one mip level, texel (i, j) of layer c at (c * N + j) * N + i.
inline std::vector<glm::vec4> readLevel(GLuint texture, int level, int side, int layers) {
  std::vector<glm::vec4> texels(static_cast<size_t>(side) * side * layers);
  glGetTextureImage(texture, level, GL_RGBA, GL_FLOAT,
                    static_cast<GLsizei>(texels.size() * sizeof(glm::vec4)), texels.data());
  return texels;
}

inline std::vector<glm::vec4> readSlope(const postfx::water::Ocean& ocean) {
  return readLevel(ocean.slopeTexture(), 0, ocean.resolution(), ocean.cascadeCount());
}

inline std::vector<glm::vec4> readDisplacement(const postfx::water::Ocean& ocean) {
  return readLevel(ocean.displacementTexture(), 0, ocean.resolution(), ocean.cascadeCount());
}

inline bool allFinite(const std::vector<glm::vec4>& texels) {
  for (const glm::vec4& t : texels) {
    if (!std::isfinite(t.x) || !std::isfinite(t.y) || !std::isfinite(t.z) || !std::isfinite(t.w))
      return false;
  }
  return true;
}

// Mean of (dh/dx)^2 + (dh/dz)^2 summed over cascades (they own disjoint wavenumber bands, so
// their slope variances add).
inline double meanSquareSlope(const std::vector<glm::vec4>& slope, int resolution, int layers) {
  const size_t perLayer = static_cast<size_t>(resolution) * resolution;
  double total = 0.0;
  for (int c = 0; c < layers; ++c) {
    double sum = 0.0;
    for (size_t t = 0; t < perLayer; ++t) {
      const glm::vec4& s = slope[c * perLayer + t];
      const double sx = s.x, sz = s.y;
      sum += sx * sx + sz * sz;
    }
    total += sum / static_cast<double>(perLayer);
  }
  return total;
}

}  // namespace watertest
