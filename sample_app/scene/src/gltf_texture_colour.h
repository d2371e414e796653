#pragma once
// The mean colour of a material's base-colour texture (private to the loader): the sample
// shades and casts from one colour per material, so a textured asset gets its texture's
// average instead of the bare factor. The image is treated alike wherever it is (a bufferView
// of a .glb or .gltf, a data: URI, a file in the model's folder): the same bytes through the
// same OpenImageIO decoder, from memory. A file is read only when a base colour uses it, and
// only inside the model's folder (the buffers' rule); no other image file is ever opened.

#include <cstdint>
#include <string>

#include <tiny_gltf.h>
#include <glm/glm.hpp>

#include "gltf_preflight.h"

namespace ocean_scene::gltf {

// Images above this many pixels are not decoded (a decompression bomb costs nothing).
inline constexpr long long kMaxTexturePixels = 16ll << 20;
// Image files above this are not read (a 16-Mpixel PNG is rarely a tenth of it).
inline constexpr std::uint64_t kMaxImageFileBytes = std::uint64_t(256) << 20;

// The linear-RGB mean of `material`'s baseColorTexture (sRGB-decoded, as glTF stores it),
// when its image is PNG or JPEG (told by its first bytes); false with a short reason otherwise
// (no texture, a file outside the folder, another format, too large, undecodable: with what
// the decoder printed, "libpng error: Invalid IHDR data"). `preflight` says where images with
// a data: URI or a file are. On success `reason` holds what the decoder printed, if anything.
bool baseColourTextureMean(const tinygltf::Model& model, const Preflight& preflight,
                           const tinygltf::Material& material, glm::vec3& mean,
                           std::string& reason);

}  // namespace ocean_scene::gltf
