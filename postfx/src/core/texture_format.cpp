#include "core/texture_format.h"

#include "core/gl_enum_names.h"

namespace postfx::detail {
namespace {

// A sized format by its components: bits of red, green, blue, alpha, depth and stencil, and the
// type of its colour (or depth) components.
struct Components {
  GLenum format;
  GLint red, green, blue, alpha, depth, stencil;
  GLenum type;
};
constexpr GLenum kUnorm = GL_UNSIGNED_NORMALIZED, kSnorm = GL_SIGNED_NORMALIZED, kFloat = GL_FLOAT;
// Every format accepted by some input; an unsized texture matching none is refused as it is.
constexpr Components kSized[] = {
    {GL_RGBA8, 8, 8, 8, 8, 0, 0, kUnorm},
    {GL_RGB8, 8, 8, 8, 0, 0, 0, kUnorm},
    {GL_RGB10_A2, 10, 10, 10, 2, 0, 0, kUnorm},
    {GL_RGBA16, 16, 16, 16, 16, 0, 0, kUnorm},
    {GL_RGB16, 16, 16, 16, 0, 0, 0, kUnorm},
    {GL_RGBA8_SNORM, 8, 8, 8, 8, 0, 0, kSnorm},
    {GL_RG8_SNORM, 8, 8, 0, 0, 0, 0, kSnorm},
    {GL_RG16_SNORM, 16, 16, 0, 0, 0, 0, kSnorm},
    {GL_RGB16_SNORM, 16, 16, 16, 0, 0, 0, kSnorm},
    {GL_RGBA16_SNORM, 16, 16, 16, 16, 0, 0, kSnorm},
    {GL_RG16F, 16, 16, 0, 0, 0, 0, kFloat},
    {GL_RG32F, 32, 32, 0, 0, 0, 0, kFloat},
    {GL_RGB16F, 16, 16, 16, 0, 0, 0, kFloat},
    {GL_RGB32F, 32, 32, 32, 0, 0, 0, kFloat},
    {GL_RGBA16F, 16, 16, 16, 16, 0, 0, kFloat},
    {GL_RGBA32F, 32, 32, 32, 32, 0, 0, kFloat},
    {GL_R11F_G11F_B10F, 11, 11, 10, 0, 0, 0, kFloat},
    {GL_DEPTH_COMPONENT16, 0, 0, 0, 0, 16, 0, kUnorm},
    {GL_DEPTH_COMPONENT24, 0, 0, 0, 0, 24, 0, kUnorm},
    {GL_DEPTH_COMPONENT32, 0, 0, 0, 0, 32, 0, kUnorm},
    {GL_DEPTH_COMPONENT32F, 0, 0, 0, 0, 32, 0, kFloat},
    {GL_DEPTH24_STENCIL8, 0, 0, 0, 0, 24, 8, kUnorm},
    {GL_DEPTH32F_STENCIL8, 0, 0, 0, 0, 32, 8, kFloat},
};

GLint levelParameter(GLuint texture, GLenum pname) {
  GLint value = 0;
  glGetTextureLevelParameteriv(texture, 0, pname, &value);
  return value;
}

}  // namespace

bool isUnsizedFormat(GLenum format) {
  switch (format) {
    case GL_RED:
    case GL_RG:
    case GL_RGB:
    case GL_RGBA:
    case GL_DEPTH_COMPONENT:
    case GL_DEPTH_STENCIL:
    case GL_SRGB:
    case GL_SRGB_ALPHA:
      return true;
    default:
      return false;
  }
}

GLenum effectiveSizedFormat(GLuint texture, GLenum reported) {
  if (!isUnsizedFormat(reported)) return reported;
  // sRGB decoding is not visible in the component sizes: an unsized sRGB texture could be taken
  // for its linear twin, so it is left unmatched (refused, naming GL_SRGB8_ALPHA8).
  if (reported == GL_SRGB || reported == GL_SRGB_ALPHA) return 0;
  const Components actual{0,
                          levelParameter(texture, GL_TEXTURE_RED_SIZE),
                          levelParameter(texture, GL_TEXTURE_GREEN_SIZE),
                          levelParameter(texture, GL_TEXTURE_BLUE_SIZE),
                          levelParameter(texture, GL_TEXTURE_ALPHA_SIZE),
                          levelParameter(texture, GL_TEXTURE_DEPTH_SIZE),
                          levelParameter(texture, GL_TEXTURE_STENCIL_SIZE),
                          0};
  const GLenum type = static_cast<GLenum>(
      levelParameter(texture, actual.depth > 0 ? GL_TEXTURE_DEPTH_TYPE : GL_TEXTURE_RED_TYPE));
  for (const Components& c : kSized)
    if (c.red == actual.red && c.green == actual.green && c.blue == actual.blue &&
        c.alpha == actual.alpha && c.depth == actual.depth && c.stencil == actual.stencil &&
        c.type == type)
      return c.format;
  return 0;
}

std::string formatList(std::initializer_list<GLenum> formats) {
  std::string text;
  std::size_t i = 0;
  for (const GLenum format : formats) {
    if (i > 0) text += (i + 1 == formats.size()) ? " or " : ", ";
    text += glEnumName(format);
    ++i;
  }
  return text;
}

}  // namespace postfx::detail
