#pragma once
// The one synthetic G-buffer builder: analytic surfaces (planes, spheres, a height field) ray-cast
// on the CPU in double, one ray per pixel centre, and uploaded as a host would give them to the
// plugin, in any depth convention and normal encoding. The plugin's tests, the lab's report rows
// and the standalone GPU bench all build their G-buffers here, so a convention is encoded one way
// everywhere. Needs only GL, GLM and the G-buffer contract (no references, no demo), so the bench
// can carry it to a bare machine.
//
// Coordinates are camera-relative world coordinates: the camera sits at the origin, axes are the
// world's (the plugin's convention: the host's double camera position is added back by the frame).
#include <epoxy/gl.h>

#include <glkit/handle.h>

#include <functional>
#include <glm/glm.hpp>
#include <limits>
#include <vector>

namespace ocean::validation {

struct SyntheticSurface {
  enum class Kind { Plane, Sphere, HeightField };
  Kind kind = Kind::Plane;
  // Plane: a point on it and its unit normal; hit only from its front (ray against the normal).
  // Sphere: its centre and radius (m); hit from outside.
  glm::dvec3 point{0.0};
  glm::dvec3 normal{0.0, 1.0, 0.0};
  double radius = 1.0;
  // HeightField: surface y (m) at (x, z); rays march it in 0.25 m + 2% steps to `maxDistance`
  // (then bisect), normals by central differences. Seen from above only.
  std::function<double(double x, double z)> height;
  // A hit at p counts only where dot(keep.xyz, p) + keep.w >= 0: half-planes such as a step in
  // a floor. The default keeps every hit.
  glm::dvec4 keep{0.0, 0.0, 0.0, 1.0};
  glm::vec3 albedo{1.0f};  // linear [0, 1]
};

struct SyntheticScene {
  int width = 128, height = 72;
  glm::dmat4 view{1.0};        // world to view, rotation only (the camera is the origin)
  glm::dmat4 projection{1.0};  // in `depthConvention`; may have an infinite far plane
  int depthConvention = 0;     // gbuffer::DepthConvention
  int normalEncoding = 0;      // gbuffer::NormalEncoding; formats RG16_SNORM, RGBA16F, RGBA8
  GLenum albedoFormat = GL_SRGB8_ALPHA8;
  GLenum targetFormat = 0;  // 0: no target texture (the caller brings one)
  // View distance (m, along the view axis) at and beyond which a pixel is sky.
  double maxDistance = std::numeric_limits<double>::infinity();
  std::vector<SyntheticSurface> surfaces;  // the nearest hit wins
  glm::vec4 skyAlbedo{1.0f};               // the albedo texels where nothing was hit
  bool zeroNormals = false;                // store zero normals (a broken G-buffer)
  bool allSky = false;                     // depth at the far plane everywhere
};

struct SyntheticPixel {
  int surface = -1;           // index into SyntheticScene::surfaces; -1 is the sky
  glm::dvec3 position{0.0};   // camera-relative world position of the hit
  glm::dvec3 normal{0.0};     // unit, world
  double viewDistance = 0.0;  // along the view axis, m
};

// Depth is GL_DEPTH_COMPONENT32F (the sky at the convention's clear value); normals are encoded
// with the shared codec (the sky's as straight up); the target, if asked for, is cleared to 0.
class SyntheticGbuffer {
 public:
  explicit SyntheticGbuffer(const SyntheticScene& scene);

  GLuint depth() const { return textures_[0].id(); }
  GLuint normal() const { return textures_[1].id(); }
  GLuint albedo() const { return textures_[2].id(); }
  GLuint target() const { return textures_[3].id(); }
  GLenum normalFormat() const { return normalFormat_; }
  const SyntheticPixel& pixel(int x, int y) const {
    return pixels_[size_t(y) * size_t(width_) + size_t(x)];
  }
  double coverage() const;  // fraction of pixels that hit a surface

 private:
  int width_ = 0;
  GLenum normalFormat_ = 0;
  std::vector<SyntheticPixel> pixels_;
  glkit::Texture textures_[4];
};

// Window depth of a point at view-space z `viewZ` (< 0) for `projection` in `convention`.
double syntheticWindowDepth(double viewZ, const glm::dmat4& projection, int convention);

}  // namespace ocean::validation
