#pragma once
// Test scenes for the postfx GL tests: a floor (optionally stepped) and a sphere under a camera,
// as a G-buffer from the synthetic G-buffer builder (sample_app/validation), synthetic water
// textures with known slopes, and read-back helpers. Every pixel's true world position and
// surface are kept for assertions.
#include <epoxy/gl.h>

#include <glm/glm.hpp>
#include <vector>

#include <postfx/local_water.h>
#include <postfx/postfx.h>
#include <synthetic_gbuffer.h>

namespace postfxtest {

enum class Hit { Sky, Floor, Sphere };

struct SceneSpec {
  int width = 128, height = 72;
  int depthConvention = 0;  // gbuffer::DepthConvention values
  int normalEncoding = 0;   // gbuffer::NormalEncoding values
  glm::dvec3 camera{0.0, -2.0, 0.0};
  glm::dvec3 lookDirection{0.0, -0.6, -1.0};
  double fovYDegrees = 60.0, nearPlane = 0.1, farPlane = 200.0;
  double floorY = -8.0;
  double stepX = 1e30;  // the floor is at floorY2 where camera-relative x > stepX
  double floorY2 = -10.0;
  bool sphere = true;                        // sphere straddling the water level, partly on screen
  glm::dvec3 sphereCenter{2.0, -1.0, -8.0};  // camera-relative
  double sphereRadius = 2.5;
  glm::vec3 albedo{1.0f};
  bool zeroNormals = false;  // store zero normals (a broken G-buffer)
  bool allSky = false;       // depth at the far plane everywhere
};

struct PixelTruth {
  Hit hit = Hit::Sky;
  glm::dvec3 position{0.0};  // camera-relative world position
  glm::dvec3 normal{0.0};
};

// Host-owned G-buffer textures of one scene; deleted with the object.
class Scene {
 public:
  explicit Scene(const SceneSpec& spec, GLenum targetFormat = GL_RGBA32F);
  Scene(const Scene&) = delete;
  Scene& operator=(const Scene&) = delete;

  const SceneSpec& spec() const { return spec_; }
  const PixelTruth& truth(int x, int y) const { return truth_[y * spec_.width + x]; }
  GLuint depth = 0, normal = 0, albedo = 0, target = 0;
  GLenum depthFormat = GL_DEPTH_COMPONENT32F, normalFormat = 0, targetFormat = 0;
  glm::mat4 view{1.0f};
  glm::dmat4 projection{1.0};
  void clearTarget(const glm::vec4& value) const;

 private:
  SceneSpec spec_;
  ocean::validation::SyntheticGbuffer gbuffer_;
  std::vector<PixelTruth> truth_;
};

// Water surface: GL_TEXTURE_2D_ARRAY RGBA32F, `layers` cascades, mipmapped. amplitude 0 gives
// flat water; nan fills every texel with NaN.
GLuint makeWaterTexture(int size, int layers, double amplitude, bool nan = false);

// One layer whose every mip level holds the same smooth wave (one period per tile along u and v,
// slope amplitude `slope`) sampled at that level's own texel centres instead of box-filtered:
// a lookup then gives the same slopes (to bilinear interpolation error, < 1e-3 relative down
// to 16 texels) at every level of detail, so tests can compare pixels whose footprints differ.
GLuint makeLevelIndependentWaterTexture(int size, double slope);

// A water texture (RGBA32F, full mip chain) from size x size texels per cascade, row by row,
// cascade after cascade (one layer each): slopes x, z, height (m), 1. Whole periods per tile
// keep it seamless.
GLuint makeWaterTextureFromTexels(int size, const std::vector<glm::vec4>& texels);

// Three crossing sine waves, h = sum of A sin(k . x + phase) with whole periods per `tile` m
// (seamless) and amplitudes amplitude x (1, 0.6, 0.35): one cascade of size^2 texels (slopes,
// height, 1), as makeWaterTextureFromTexels.
GLuint makeCrossingWaves(int size, double tile, double amplitude);

// A local water region of zero height and slope (a GL_TEXTURE_2D RGBA32F of `size` texels a
// side, which the caller deletes), 4 m square 4 m ahead of the origin, grid 32, 2 layers: the
// smallest region that runs the local water pass.
struct FlatRegion {
  GLuint texture = 0;
  postfx::LocalWater region;
};
FlatRegion makeFlatRegion(int size);

// A reverse-Z perspective (near -> 1, far -> 0, right-handed), as most of the tests' hosts use.
glm::dmat4 reverseZPerspective(double fovYDegrees, double aspect, double nearPlane,
                               double farPlane);

// A frame for `scene` with the caustics defaults but the RayDeviation model, water at `level`
// (world), camera at scene.camera + offset (the whole scene moved by `offset`).
postfx::FrameDesc makeFrame(const Scene& scene, GLuint water, int cascades,
                            const glm::dvec3& offset = glm::dvec3(0.0), double level = 0.0);

std::vector<float> readRed(GLuint texture, int width, int height);
std::vector<glm::vec4> readRgba(GLuint texture, int width, int height);

}  // namespace postfxtest
