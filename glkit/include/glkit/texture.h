#pragma once
// Creating the plain, single-level, clamped 2D textures render targets are made of, and the
// sampler objects passes read textures with.
#include <epoxy/gl.h>

#include <glkit/handle.h>

#include <bit>
#include <string_view>

namespace glkit {

// Levels of a full mip chain for a texture `size` texels on its longest side (1 for size 1).
inline int mipLevelCount(int size) {
  return std::bit_width(static_cast<unsigned>(size));
}

// Width of level 0 of `texture`, 0 when it has no storage: glTextureStorage* that the driver
// refused (GL_OUT_OF_MEMORY) leaves the texture without levels, which is how a pass finds out
// before it draws anything.
inline int storedWidth(const Texture& texture) {
  GLint width = 0;
  if (texture) glGetTextureLevelParameteriv(texture.id(), 0, GL_TEXTURE_WIDTH, &width);
  return width;
}

// One mip level, clamp-to-edge, `filter` for both min and mag (render targets are read
// texel-exact: GL_NEAREST unless the reader interpolates on purpose), labelled for debuggers.
Texture createTexture2D(GLenum format, int width, int height, GLenum filter,
                        std::string_view label);

// A sampler object with these filters and wrap on s and t, depth comparison off (a host depth
// texture may carry GL_COMPARE_REF_TO_TEXTURE; the sampler decides, not the texture), labelled.
Sampler createSampler(GLenum minFilter, GLenum magFilter, GLenum wrap, std::string_view label);

}  // namespace glkit
