#include "gbuffer_readback.h"

#include <epoxy/gl.h>

#include <cmath>

#include <gbuffer/codec.h>

namespace ocean::reference {
namespace {

bool sizeOf(GLuint texture, int& width, int& height) {
  if (texture == 0 || glIsTexture(texture) != GL_TRUE) return false;
  glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_WIDTH, &width);
  glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_HEIGHT, &height);
  return width > 0 && height > 0;
}

// The exact sRGB decode GL applies when a shader samples an sRGB texture.
float srgbToLinear(float c) {
  return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

}  // namespace

bool readGBuffer(const postfx::CreateDesc& create, const postfx::FrameDesc& frame, GBufferCopy& out,
                 std::string& error) {
  int width = 0, height = 0, w = 0, h = 0;
  if (!sizeOf(frame.depth.texture, width, height) || !sizeOf(frame.normal.texture, w, h) ||
      w != width || h != height || !sizeOf(frame.albedo.texture, w, h) || w != width ||
      h != height) {
    error = "G-buffer textures are missing or of different sizes";
    return false;
  }
  const size_t n = static_cast<size_t>(width) * static_cast<size_t>(height);
  std::vector<float> depth(n);
  std::vector<glm::vec4> normal(n), albedo(n);
  glGetTextureImage(frame.depth.texture, 0, GL_DEPTH_COMPONENT, GL_FLOAT,
                    static_cast<GLsizei>(n * sizeof(float)), depth.data());
  glGetTextureImage(frame.normal.texture, 0, GL_RGBA, GL_FLOAT,
                    static_cast<GLsizei>(n * sizeof(glm::vec4)), normal.data());
  GLint albedoFormat = 0;
  glGetTextureLevelParameteriv(frame.albedo.texture, 0, GL_TEXTURE_INTERNAL_FORMAT, &albedoFormat);
  const bool srgb = albedoFormat == GL_SRGB8_ALPHA8 || albedoFormat == GL_SRGB8;
  if (srgb) {
    // Read the stored bytes and decode here: GL does not decode sRGB on read-back.
    std::vector<std::uint8_t> bytes(n * 4);
    glGetTextureImage(frame.albedo.texture, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                      static_cast<GLsizei>(bytes.size()), bytes.data());
    for (size_t i = 0; i < n; ++i) {
      for (int c = 0; c < 3; ++c) albedo[i][c] = srgbToLinear(bytes[4 * i + c] / 255.0f);
    }
  } else {
    glGetTextureImage(frame.albedo.texture, 0, GL_RGBA, GL_FLOAT,
                      static_cast<GLsizei>(n * sizeof(glm::vec4)), albedo.data());
  }
  const gbuffer::ProjectionParams params = gbuffer::projectionParams(
      frame.camera.projection, static_cast<gbuffer::DepthConvention>(create.depthConvention));
  const int depthConvention = static_cast<int>(create.depthConvention);
  const int normalEncoding = static_cast<int>(create.normalEncoding);
  out.width = width;
  out.height = height;
  out.viewPosition.assign(n, glm::dvec3(0.0));
  out.normal.assign(n, glm::dvec3(0.0));
  out.albedo.assign(n, glm::vec3(0.0f));
  out.sky.assign(n, 1);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const size_t i = static_cast<size_t>(y) * width + x;
      out.albedo[i] = glm::vec3(albedo[i]);
      if (gbuffer::shared::isSkyDepth(depth[i], depthConvention)) continue;
      out.sky[i] = 0;
      const glm::vec2 uv(static_cast<float>((x + 0.5) / width),
                         static_cast<float>((y + 0.5) / height));
      out.viewPosition[i] = glm::dvec3(gbuffer::shared::viewPositionFromDepth(
          uv, depth[i], params.xy, params.z, depthConvention));
      out.normal[i] = glm::dvec3(gbuffer::shared::decodeNormal(normal[i], normalEncoding));
    }
  }
  return true;
}

FrameReceivers receiversOf(const postfx::FrameDesc& frame, const GBufferCopy& gbuffer) {
  const glm::dvec4 projection(frame.camera.projection[0][0], frame.camera.projection[1][1],
                              frame.camera.projection[2][0], frame.camera.projection[2][1]);
  return makeFrameReceivers(gbuffer.width, gbuffer.height, frame.camera.position,
                            glm::dmat3(glm::mat3(frame.camera.view)), projection, frame.water.level,
                            gbuffer.viewPosition, gbuffer.normal, gbuffer.sky);
}

}  // namespace ocean::reference
