// The smallest complete host of the installed postfx package: a headless GL context, a G-buffer
// of a flat seabed 6 m below the water seen from straight above, a sine-wave water surface, and
// one dispatch that adds seabed caustics into an HDR target. It checks what any host may rely
// on: a bad frame is refused and draws nothing; a good one adds finite, patterned light to the
// seabed and none where nothing was drawn. Exit 0 when all hold, 1 (with one line) otherwise.
#include <epoxy/gl.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include <postfx/postfx.h>
#include <glm/gtc/matrix_transform.hpp>

#include "headless_gl.h"

namespace {

constexpr int kWidth = 160, kHeight = 90;
constexpr double kWaterLevel = 0.0, kSeabedY = -6.0;
constexpr double kTileSize = 4.0;  // metres per water tile
constexpr int kWaterTexels = 128;

struct Texture {
  GLuint name = 0;
  Texture(GLenum target, GLenum format, int width, int height, int layers = 1) {
    glCreateTextures(target, 1, &name);
    if (target == GL_TEXTURE_2D_ARRAY) {
      glTextureStorage3D(name, 1, format, width, height, layers);
    } else {
      glTextureStorage2D(name, 1, format, width, height);
    }
  }
  ~Texture() { glDeleteTextures(1, &name); }
  Texture(const Texture&) = delete;
  Texture& operator=(const Texture&) = delete;
};

int fail(const std::string& message) {
  std::fprintf(stderr, "minimal_host: %s\n", message.c_str());
  return 1;
}

// Forward [0,1] depth of the seabed along each pixel's ray, 1 (nothing drawn) on the right
// half of the image so the host can check that no light lands where it drew nothing.
std::vector<float> seabedDepth(const glm::dmat4& viewProjection, const glm::dmat4& inverse,
                               const glm::dvec3& eye) {
  std::vector<float> depth(std::size_t(kWidth) * kHeight, 1.0f);
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth / 2; ++x) {
      const glm::dvec4 ndc((x + 0.5) / kWidth * 2.0 - 1.0, (y + 0.5) / kHeight * 2.0 - 1.0, 0.5,
                           1.0);
      glm::dvec4 world = inverse * ndc;
      const glm::dvec3 direction = glm::normalize(glm::dvec3(world) / world.w - eye);
      const double t = (kSeabedY - eye.y) / direction.y;
      const glm::dvec4 clip = viewProjection * glm::dvec4(eye + t * direction, 1.0);
      depth[std::size_t(y) * kWidth + x] = float(clip.z / clip.w);
    }
  }
  return depth;
}

// Slopes (dh/dx, dh/dz) of h = a sin(kx) sin(kz), two periods per tile: waves that focus the
// sun into a grid of bright spots a few metres down.
std::vector<float> waterSlopes() {
  const double k = 2.0 * 2.0 * std::numbers::pi / kTileSize, amplitude = 0.04;
  std::vector<float> slopes(std::size_t(kWaterTexels) * kWaterTexels * 2);
  for (int j = 0; j < kWaterTexels; ++j) {
    for (int i = 0; i < kWaterTexels; ++i) {
      const double x = (i + 0.5) / kWaterTexels * kTileSize;
      const double z = (j + 0.5) / kWaterTexels * kTileSize;
      float* texel = &slopes[(std::size_t(j) * kWaterTexels + i) * 2];
      texel[0] = float(amplitude * k * std::cos(k * x) * std::sin(k * z));
      texel[1] = float(amplitude * k * std::sin(k * x) * std::cos(k * z));
    }
  }
  return slopes;
}

std::vector<float> readTarget(GLuint target) {
  std::vector<float> pixels(std::size_t(kWidth) * kHeight * 4);
  glGetTextureImage(target, 0, GL_RGBA, GL_FLOAT, GLsizei(pixels.size() * sizeof(float)),
                    pixels.data());
  return pixels;
}

}  // namespace

int main() {
  HeadlessGl gl;
  std::string error;
  if (!createHeadlessGl(gl, error)) return fail(error);

  // The G-buffer a deferred renderer has after its lighting pass.
  const glm::dvec3 eye(0.3, -1.0, 0.7);
  const glm::dmat4 view =
      glm::lookAt(glm::dvec3(0.0), glm::dvec3(0.0, -1.0, 0.0), glm::dvec3(0.0, 0.0, -1.0));
  const glm::dmat4 projection =
      glm::perspectiveRH_ZO(glm::radians(60.0), double(kWidth) / kHeight, 0.1, 100.0);
  const glm::dmat4 viewProjection = projection * view * glm::translate(glm::dmat4(1.0), -eye);
  const std::vector<float> depth = seabedDepth(viewProjection, glm::inverse(viewProjection), eye);
  Texture depthTexture(GL_TEXTURE_2D, GL_DEPTH_COMPONENT32F, kWidth, kHeight);
  glTextureSubImage2D(depthTexture.name, 0, 0, 0, kWidth, kHeight, GL_DEPTH_COMPONENT, GL_FLOAT,
                      depth.data());
  Texture normal(GL_TEXTURE_2D, GL_RGBA16F, kWidth, kHeight);
  const float up[4] = {0.0f, 1.0f, 0.0f, 0.0f};
  glClearTexImage(normal.name, 0, GL_RGBA, GL_FLOAT, up);
  Texture albedo(GL_TEXTURE_2D, GL_RGBA8, kWidth, kHeight);
  const float sand[4] = {0.8f, 0.75f, 0.6f, 1.0f};
  glClearTexImage(albedo.name, 0, GL_RGBA, GL_FLOAT, sand);
  Texture target(GL_TEXTURE_2D, GL_RGBA16F, kWidth, kHeight);
  const float black[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  glClearTexImage(target.name, 0, GL_RGBA, GL_FLOAT, black);
  Texture water(GL_TEXTURE_2D_ARRAY, GL_RG32F, kWaterTexels, kWaterTexels, 1);
  const std::vector<float> slopes = waterSlopes();
  glTextureSubImage3D(water.name, 0, 0, 0, 0, kWaterTexels, kWaterTexels, 1, GL_RG, GL_FLOAT,
                      slopes.data());

  postfx::CreateDesc create;
  create.features = postfx::Feature::Caustics;
  create.depthConvention = postfx::DepthConvention::ForwardZeroToOne;
  create.normalEncoding = postfx::NormalEncoding::WorldXyz;
  create.maxWaterCascades = 1;
  postfx::Context* fx = nullptr;
  if (postfx::create(create, fx) != postfx::Result::Ok) {
    return fail(std::string("create: ") + postfx::lastError(nullptr));
  }

  postfx::FrameDesc frame;
  frame.depth = {depthTexture.name, GL_DEPTH_COMPONENT32F};
  frame.normal = {normal.name, GL_RGBA16F};
  frame.albedo = {albedo.name, GL_RGBA8};
  frame.target = {target.name, GL_RGBA16F};
  frame.camera.position = eye;
  frame.camera.view = glm::mat4(view);
  frame.camera.projection = projection;
  frame.sun.direction = glm::normalize(glm::dvec3(0.2, 1.0, 0.1));
  frame.sun.irradiance = glm::vec3(1.0f);
  frame.water.level = kWaterLevel;
  frame.water.texture = {water.name, GL_RG32F};
  frame.water.cascadeCount = 1;
  frame.water.tileSize[0] = kTileSize;

  // A bad frame is refused with a message and draws nothing.
  postfx::FrameDesc bad = frame;
  bad.water.ior = std::nanf("");
  if (postfx::dispatch(*fx, bad) == postfx::Result::Ok) return fail("a NaN IOR was accepted");
  const std::string refusal = postfx::lastError(fx);
  for (float value : readTarget(target.name)) {
    if (value != 0.0f) return fail("a refused frame wrote into the target");
  }

  if (postfx::dispatch(*fx, frame) != postfx::Result::Ok) {
    return fail(std::string("dispatch: ") + postfx::lastError(fx));
  }
  const std::vector<float> light = readTarget(target.name);
  postfx::destroy(fx);
  if (glGetError() != GL_NO_ERROR) return fail("GL error after dispatch");

  double sum = 0.0, sumSquares = 0.0, low = 1e30, high = 0.0;
  int seabed = 0;
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      const float* p = &light[(std::size_t(y) * kWidth + x) * 4];
      for (int c = 0; c < 3; ++c) {
        if (!std::isfinite(p[c]) || p[c] < 0.0f) return fail("non-finite or negative light");
      }
      if (x >= kWidth / 2) {
        if (p[0] != 0.0f || p[1] != 0.0f || p[2] != 0.0f)
          return fail("light where nothing was drawn");
        continue;
      }
      const double g = p[1];
      sum += g;
      sumSquares += g * g;
      low = std::min(low, g);
      high = std::max(high, g);
      ++seabed;
    }
  }
  const double mean = sum / seabed;
  const double contrast = std::sqrt(std::max(0.0, sumSquares / seabed - mean * mean)) / mean;
  if (!(mean > 0.0)) return fail("no caustic light on the seabed");
  if (!(contrast > 0.05))
    return fail("caustic light has no pattern (contrast " + std::to_string(contrast) + ")");
  std::printf(
      "minimal_host: refused a bad frame (\"%s\"), then added caustics: seabed green mean %.4f, "
      "min %.4f, max %.4f, contrast %.3f; nothing where no surface was drawn\n",
      refusal.c_str(), mean, low, high, contrast);
  return 0;
}
