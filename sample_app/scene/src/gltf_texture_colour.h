#pragma once
// The mean colour of a material's base-colour texture (private to the loader): the sample
// shades and casts from one colour per material, so a textured asset gets its texture's
// average instead of the bare factor. Only images embedded in the file (a bufferView) are
// decoded, through OpenImageIO from memory: external image files are still never opened.

#include <string>

#include <tiny_gltf.h>
#include <glm/glm.hpp>

namespace ocean_scene::gltf {

// Images above this many pixels are not decoded (a decompression bomb costs nothing).
inline constexpr long long kMaxTexturePixels = 16ll << 20;

// The linear-RGB mean of `material`'s baseColorTexture (sRGB-decoded, as glTF stores it),
// when that texture's image is embedded as PNG or JPEG; false with a short reason otherwise
// (no texture, an external file, another format, too large, undecodable).
bool baseColourTextureMean(const tinygltf::Model& model, const tinygltf::Material& material,
                           glm::vec3& mean, std::string& reason);

}  // namespace ocean_scene::gltf
