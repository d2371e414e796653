#pragma once
// The mean colour of a material's base-colour texture (private to the loader): the sample
// shades and casts from one colour per material, so a textured asset gets its texture's
// average instead of the bare factor. The image is treated alike wherever it is (a bufferView
// of a .glb or .gltf, a data: URI, a file in the model's folder): the same bytes through the
// same OpenImageIO decoder, from memory. A file is read only when a base colour uses it, and
// only inside the model's folder (the buffers' rule); no other image file is ever opened.

#include <cstdint>
#include <map>
#include <string>

#include <tiny_gltf.h>
#include <glm/glm.hpp>

#include "gltf_preflight.h"
#include "scene/gltf_limits.h"

namespace ocean_scene::gltf {

// Images above this many pixels are not decoded (a decompression bomb costs nothing).
inline constexpr long long kMaxTexturePixels = 16ll << 20;
// Image files above this are not read (a 16-Mpixel PNG is rarely a tenth of it).
inline constexpr std::uint64_t kMaxImageFileBytes = std::uint64_t(256) << 20;

// What one image gave: its linear-RGB mean (sRGB-decoded, as glTF stores it), or why not.
struct ImageMean {
  bool decodable = false;  // its header was read and is within kMaxTexturePixels
  bool averaged = false;   // `mean` holds its mean
  glm::vec3 mean{1.0f};
  std::string reason;  // why not, or what the decoder printed
};
// By image index.
using ImageMeans = std::map<int, ImageMean>;

// The mean of every image a material's base colour uses, each decoded once however many
// materials share it (one 4096^2 PNG shared by 2,000 materials was decoded 2,000 times, for
// minutes). Before any is decoded, the pixels all of them will decode to (width x height from
// each header) are held to limits.pixels: false with the work budget's refusal. An image that
// cannot be averaged (not PNG or JPEG, too large, a file outside the folder, undecodable: with
// what the decoder printed, "libpng error: Invalid IHDR data") has its reason instead.
// `preflight` says where images with a data: URI or a file are.
bool baseColourImageMeans(const tinygltf::Model& model, const Preflight& preflight,
                          const GltfLimits& limits, ImageMeans& means, std::string& error);

// The mean of `material`'s baseColorTexture from `means`; false with a short reason otherwise
// (no texture, or its image's reason). On success `reason` holds what the decoder printed, if
// anything.
bool baseColourTextureMean(const tinygltf::Model& model, const ImageMeans& means,
                           const tinygltf::Material& material, glm::vec3& mean,
                           std::string& reason);

}  // namespace ocean_scene::gltf
