#include "gltf_texture_colour.h"

#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include "gltf_budget.h"
#include "gltf_data_uri.h"
#include "gltf_file.h"
#include "gltf_stderr.h"

namespace ocean_scene::gltf {

namespace {

double srgbToLinear(double c) {
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

std::uint32_t crc32(const unsigned char* data, std::size_t size) {
  static const std::array<std::uint32_t, 256> table = [] {
    std::array<std::uint32_t, 256> t{};
    for (std::uint32_t n = 0; n < 256; ++n) {
      std::uint32_t c = n;
      for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0xedb88320u & (0u - (c & 1u)));
      t[n] = c;
    }
    return t;
  }();
  std::uint32_t crc = 0xffffffffu;
  for (std::size_t i = 0; i < size; ++i) crc = table[(crc ^ data[i]) & 0xffu] ^ (crc >> 8);
  return ~crc;
}

std::uint32_t bigEndian(const unsigned char* p) {
  return (std::uint32_t(p[0]) << 24) | (std::uint32_t(p[1]) << 16) | (std::uint32_t(p[2]) << 8) |
         std::uint32_t(p[3]);
}

// Whether a PNG's chunk structure is whole: the signature, IHDR first, every chunk inside the
// data with a letter type and a matching CRC, IEND reached. OpenImageIO 2.4 reads PNG through
// libpng's default error handler, which prints on stderr; damaged or cut files are refused
// here so that it never sees them (a file with valid CRCs over bad pixel data still can).
bool pngChunksWhole(const unsigned char* data, std::size_t size) {
  static const unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (size < 8 || std::memcmp(data, kSignature, 8) != 0) return false;
  std::size_t at = 8;
  bool first = true;
  while (size - at >= 12) {
    const std::uint32_t length = bigEndian(data + at);
    if (length > size - at - 12) return false;
    const unsigned char* type = data + at + 4;
    for (int i = 0; i < 4; ++i) {
      if (!std::isalpha(type[i])) return false;
    }
    if (first && (std::memcmp(type, "IHDR", 4) != 0 || length != 13)) return false;
    if (bigEndian(data + at + 8 + length) != crc32(type, 4 + std::size_t(length))) return false;
    if (std::memcmp(type, "IEND", 4) == 0) return true;
    at += 12 + std::size_t(length);
    first = false;
  }
  return false;
}

// The image's encoded bytes, from wherever the file keeps them; false with the reason.
bool imageBytes(const tinygltf::Model& model, const Preflight& preflight, int source,
                std::vector<unsigned char>& owned, const unsigned char*& bytes, std::size_t& size,
                std::string& reason) {
  const tinygltf::Image& image = model.images[std::size_t(source)];
  if (image.bufferView >= 0) {
    if (static_cast<std::size_t>(image.bufferView) >= model.bufferViews.size()) {
      reason = "its image's bufferView does not exist";
      return false;
    }
    const tinygltf::BufferView& view = model.bufferViews[std::size_t(image.bufferView)];
    if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= model.buffers.size()) {
      reason = "its image's bufferView has no buffer";
      return false;
    }
    const std::vector<unsigned char>& data = model.buffers[std::size_t(view.buffer)].data;
    if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset) {
      reason = "its image's bufferView lies outside its buffer";
      return false;
    }
    bytes = data.data() + view.byteOffset;
    size = view.byteLength;
    return true;
  }
  const auto found = preflight.baseColourImages.find(std::size_t(source));
  if (found == preflight.baseColourImages.end()) {
    reason = "its image has neither a bufferView nor a uri";
    return false;
  }
  const ImageSource& where = found->second;
  if (!where.dataUri.empty()) {
    owned = decodeDataUri(where.dataUri);
  } else if (!where.file.empty()) {
    std::string problem;
    if (!readRegularFile(where.file, kMaxImageFileBytes, owned, problem)) {
      reason = "its file " + problem;
      return false;
    }
  } else {
    reason = where.problem;
    return false;
  }
  bytes = owned.data();
  size = owned.size();
  return true;
}

// OpenImageIO's reader for the bytes, told by their signature (as a file's name would tell
// it); nullptr for anything but PNG and JPEG.
const char* readerName(const unsigned char* bytes, std::size_t size) {
  static const unsigned char kPng[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (size >= 8 && std::memcmp(bytes, kPng, 8) == 0) return "image.png";
  if (size >= 3 && bytes[0] == 0xFF && bytes[1] == 0xD8 && bytes[2] == 0xFF) return "image.jpg";
  return nullptr;
}

// The image's header, through the reader OpenImageIO picks for `name`: its size, before any
// pixel is decoded. False with the reason (undecodable, empty, over kMaxTexturePixels).
bool readHeader(const unsigned char* bytes, std::size_t size, const char* name,
                OIIO::ImageSpec& spec, std::string& reason) {
  OIIO::Filesystem::IOMemReader memory(bytes, size);
  auto input = OIIO::ImageInput::open(name, nullptr, &memory);
  if (!input) {
    (void)OIIO::geterror();  // consumed, so it is not reported later by someone else
    reason = "its image could not be decoded";
    return false;
  }
  spec = input->spec();
  const long long pixels = static_cast<long long>(spec.width) * spec.height;
  if (spec.width <= 0 || spec.height <= 0 || spec.depth != 1 || spec.nchannels < 1 ||
      pixels > kMaxTexturePixels) {
    reason =
        "its image is empty or larger than " + std::to_string(kMaxTexturePixels >> 20) + " Mpixels";
    return false;
  }
  return true;
}

// The decoded texels of the image as floats; false with the reason.
bool decode(const unsigned char* bytes, std::size_t size, const char* name, OIIO::ImageSpec& spec,
            std::vector<float>& texels, std::string& reason) {
  if (!readHeader(bytes, size, name, spec, reason)) return false;
  OIIO::Filesystem::IOMemReader memory(bytes, size);
  auto input = OIIO::ImageInput::open(name, nullptr, &memory);
  if (!input) {
    (void)OIIO::geterror();
    reason = "its image could not be decoded";
    return false;
  }
  const long long pixels = static_cast<long long>(spec.width) * spec.height;
  texels.resize(static_cast<std::size_t>(pixels) * std::size_t(spec.nchannels));
  if (!input->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, texels.data())) {
    (void)input->geterror();
    reason = "its image could not be decoded";
    return false;
  }
  return true;
}

// Whatever a decoder printed on stderr meanwhile (libpng reports through its default handlers)
// is appended to `reason`.
template <class Step>
bool capturing(std::string& reason, Step step) {
  StderrCapture capture;
  const bool ok = step();
  if (const std::string printed = capture.take(); !printed.empty()) {
    reason += (reason.empty() ? "" : ": ") + printed;
  }
  return ok;
}

// The image's bytes and reader, checked as far as can be without decoding: false with the
// reason (not PNG or JPEG, a damaged PNG, a file not read).
bool encoded(const tinygltf::Model& model, const Preflight& preflight, int source,
             std::vector<unsigned char>& owned, const unsigned char*& bytes, std::size_t& size,
             const char*& name, std::string& reason) {
  if (!imageBytes(model, preflight, source, owned, bytes, size, reason)) return false;
  name = readerName(bytes, size);
  if (name == nullptr) {
    reason = "its image is not PNG or JPEG";
    return false;
  }
  if (std::strcmp(name, "image.png") == 0 && !pngChunksWhole(bytes, size)) {
    reason = "its PNG is damaged or cut short";
    return false;
  }
  return true;
}

// The linear-RGB mean of the decoded image.
bool meanOf(const unsigned char* bytes, std::size_t size, const char* name, glm::vec3& mean,
            std::string& reason) {
  OIIO::ImageSpec spec;
  std::vector<float> texels;
  if (!capturing(reason, [&] { return decode(bytes, size, name, spec, texels, reason); })) {
    return false;
  }
  const int channels = spec.nchannels;
  const long long pixels = static_cast<long long>(spec.width) * spec.height;
  glm::dvec3 sum(0.0);
  for (long long p = 0; p < pixels; ++p) {
    const float* t = &texels[std::size_t(p) * std::size_t(channels)];
    for (int c = 0; c < 3; ++c) {
      const double v = t[channels >= 3 ? c : 0];  // grey images repeat their one channel
      sum[c] += srgbToLinear(std::fmin(std::fmax(v, 0.0), 1.0));
    }
  }
  mean = glm::vec3(sum / double(pixels));
  return true;
}

// The image a material's base colour uses, or -1 with the reason.
int baseColourImage(const tinygltf::Model& model, const tinygltf::Material& material,
                    std::string& reason) {
  const int textureIndex = material.pbrMetallicRoughness.baseColorTexture.index;
  if (textureIndex < 0 || static_cast<std::size_t>(textureIndex) >= model.textures.size()) {
    reason = "no base-colour texture";
    return -1;
  }
  const int source = model.textures[std::size_t(textureIndex)].source;
  if (source < 0 || static_cast<std::size_t>(source) >= model.images.size()) {
    reason = "its texture has no image";
    return -1;
  }
  return source;
}

}  // namespace

bool baseColourImageMeans(const tinygltf::Model& model, const Preflight& preflight,
                          const GltfLimits& limits, ImageMeans& means, std::string& error) {
  means.clear();
  std::string unused;
  for (const tinygltf::Material& material : model.materials) {
    const int source = baseColourImage(model, material, unused);
    if (source >= 0) means[source] = ImageMean{};
  }
  // The pixels every image will decode to, from the headers: refused before any is decoded.
  std::uint64_t pixels = 0;
  for (auto& [source, image] : means) {
    std::vector<unsigned char> owned;
    const unsigned char* bytes = nullptr;
    std::size_t size = 0;
    const char* name = nullptr;
    OIIO::ImageSpec spec;
    image.decodable =
        encoded(model, preflight, source, owned, bytes, size, name, image.reason) &&
        capturing(image.reason, [&] { return readHeader(bytes, size, name, spec, image.reason); });
    if (image.decodable) pixels += std::uint64_t(spec.width) * std::uint64_t(spec.height);
  }
  if (pixels > limits.pixels) {
    error = refusal(std::to_string(pixels) + " texture pixels to decode, " +
                        std::to_string(means.size()) + " image(s) (limit " +
                        std::to_string(limits.pixels) + ")",
                    "pixels=N", limits);
    return false;
  }
  for (auto& [source, image] : means) {
    if (!image.decodable) continue;
    std::vector<unsigned char> owned;
    const unsigned char* bytes = nullptr;
    std::size_t size = 0;
    const char* name = nullptr;
    image.averaged = encoded(model, preflight, source, owned, bytes, size, name, image.reason) &&
                     meanOf(bytes, size, name, image.mean, image.reason);
  }
  return true;
}

bool baseColourTextureMean(const tinygltf::Model& model, const ImageMeans& means,
                           const tinygltf::Material& material, glm::vec3& mean,
                           std::string& reason) {
  reason.clear();
  const int source = baseColourImage(model, material, reason);
  if (source < 0) return false;
  const auto found = means.find(source);
  if (found == means.end()) {
    reason = "its image was not read";
    return false;
  }
  reason = found->second.reason;
  if (!found->second.averaged) return false;
  mean = found->second.mean;
  return true;
}

}  // namespace ocean_scene::gltf
