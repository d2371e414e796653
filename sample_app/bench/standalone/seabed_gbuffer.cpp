#include "seabed_gbuffer.h"

#include <cmath>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

namespace postfx::bench {
namespace {

// Dunes and ripples: 4-9 m below the water level at y = 0.
double seabedHeight(double x, double z) {
  return -6.5 + 1.6 * std::sin(0.21 * x + 0.4) * std::cos(0.17 * z) +
         0.6 * std::sin(0.9 * x - 0.5 * z) + 0.08 * std::sin(4.1 * x + 2.3 * z);
}

glm::dvec3 seabedNormal(double x, double z) {
  const double e = 1e-3;
  const double dx = (seabedHeight(x + e, z) - seabedHeight(x - e, z)) / (2.0 * e);
  const double dz = (seabedHeight(x, z + e) - seabedHeight(x, z - e)) / (2.0 * e);
  return glm::normalize(glm::dvec3(-dx, 1.0, -dz));
}

// First crossing of the ray with the height field within 80 m, or a negative t.
double marchSeabed(const glm::dvec3& origin, const glm::dvec3& direction) {
  double previous = 0.0;
  for (double t = 0.25; t < 80.0; t += 0.25 + 0.02 * t) {
    const glm::dvec3 p = origin + t * direction;
    if (p.y < seabedHeight(p.x, p.z)) {
      double lo = previous, hi = t;
      for (int i = 0; i < 24; ++i) {
        const double mid = 0.5 * (lo + hi);
        const glm::dvec3 q = origin + mid * direction;
        (q.y < seabedHeight(q.x, q.z) ? hi : lo) = mid;
      }
      return hi;
    }
    previous = t;
  }
  return -1.0;
}

}  // namespace

SeabedGbuffer::SeabedGbuffer(int width, int height) {
  const double aspect = double(width) / height;
  view_.view = glm::lookAt(glm::dvec3(0.0), glm::dvec3(0.0, -std::tan(glm::radians(20.0)), -1.0),
                           glm::dvec3(0.0, 1.0, 0.0));
  view_.projection = glm::perspectiveRH_ZO(glm::radians(60.0), aspect, 0.1, 200.0);
  const glm::dmat4 viewProjection =
      view_.projection * view_.view * glm::translate(glm::dmat4(1.0), -view_.eye);
  const glm::dmat4 inverse = glm::inverse(viewProjection);

  const size_t count = size_t(width) * size_t(height);
  std::vector<float> depth(count, 1.0f), normal(count * 4, 0.0f);
  std::vector<unsigned char> albedo(count * 4, 0);
  size_t seabed = 0;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const glm::dvec4 ndc((x + 0.5) / width * 2.0 - 1.0, (y + 0.5) / height * 2.0 - 1.0, 0.5, 1.0);
      const glm::dvec4 world = inverse * ndc;
      const glm::dvec3 direction = glm::normalize(glm::dvec3(world) / world.w - view_.eye);
      const double t = marchSeabed(view_.eye, direction);
      if (t < 0.0) continue;
      const glm::dvec3 p = view_.eye + t * direction;
      const glm::dvec4 clip = viewProjection * glm::dvec4(p, 1.0);
      const size_t i = size_t(y) * size_t(width) + size_t(x);
      depth[i] = float(clip.z / clip.w);
      const glm::dvec3 n = seabedNormal(p.x, p.z);
      for (int c = 0; c < 3; ++c) normal[i * 4 + size_t(c)] = float(n[c]);
      const unsigned char sand[4] = {204, 190, 150, 255};
      for (int c = 0; c < 4; ++c) albedo[i * 4 + size_t(c)] = sand[c];
      ++seabed;
    }
  }
  seabedFraction_ = double(seabed) / double(count);

  glCreateTextures(GL_TEXTURE_2D, 4, textures_);
  glTextureStorage2D(textures_[0], 1, GL_DEPTH_COMPONENT32F, width, height);
  glTextureSubImage2D(textures_[0], 0, 0, 0, width, height, GL_DEPTH_COMPONENT, GL_FLOAT,
                      depth.data());
  glTextureStorage2D(textures_[1], 1, GL_RGBA16F, width, height);
  glTextureSubImage2D(textures_[1], 0, 0, 0, width, height, GL_RGBA, GL_FLOAT, normal.data());
  glTextureStorage2D(textures_[2], 1, GL_RGBA8, width, height);
  glTextureSubImage2D(textures_[2], 0, 0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE,
                      albedo.data());
  glTextureStorage2D(textures_[3], 1, GL_RGBA16F, width, height);
}

SeabedGbuffer::~SeabedGbuffer() {
  glDeleteTextures(4, textures_);
}

}  // namespace postfx::bench
