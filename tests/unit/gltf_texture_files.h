#pragma once
// glTF files with an embedded base-colour texture, written by the tests themselves (no
// committed blobs): a small PNG made through OpenImageIO, the same PNG with a header claiming
// a huge size, and a GLB whose one material uses the image.

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <OpenImageIO/imageio.h>

#include "gltf_test_files.h"

namespace gltf_texture_files {

namespace fs = std::filesystem;
using Bytes = std::vector<unsigned char>;

// A size x size PNG (2x2 by default) of one sRGB colour, through OpenImageIO.
inline Bytes png(const fs::path& path, const unsigned char rgb[3], int size = 2) {
  auto out = OIIO::ImageOutput::create(path.string());
  if (!out) return {};
  const OIIO::ImageSpec spec(size, size, 3, OIIO::TypeDesc::UINT8);
  std::vector<unsigned char> texels;
  for (int i = 0; i < size * size; ++i) texels.insert(texels.end(), rgb, rgb + 3);
  if (!(out->open(path.string(), spec) && out->write_image(OIIO::TypeDesc::UINT8, texels.data()) &&
        out->close()))
    return {};
  std::ifstream in(path, std::ios::binary);
  return Bytes(std::istreambuf_iterator<char>(in), {});
}

// CRC-32 (PNG's), to keep a patched header valid.
inline std::uint32_t crc32(const unsigned char* data, std::size_t size) {
  std::uint32_t crc = 0xffffffffu;
  for (std::size_t i = 0; i < size; ++i) {
    crc ^= data[i];
    for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
  }
  return ~crc;
}

// The PNG with its IHDR claiming width x height (a decompression bomb's header).
inline Bytes claimSize(Bytes image, std::uint32_t width, std::uint32_t height) {
  // Signature (8), IHDR length (4), "IHDR" (4), then width and height, big-endian.
  for (int i = 0; i < 4; ++i) {
    image[16 + i] = static_cast<unsigned char>(width >> (24 - 8 * i));
    image[20 + i] = static_cast<unsigned char>(height >> (24 - 8 * i));
  }
  const std::uint32_t crc = crc32(image.data() + 12, 17);  // "IHDR" and its 13 bytes
  for (int i = 0; i < 4; ++i) image[29 + i] = static_cast<unsigned char>(crc >> (24 - 8 * i));
  return image;
}

// The PNG with byte `at` of its IHDR data (0..12: width, height, bit depth at 8, colour type at
// 9, ...) set to `value`, the chunk's CRC kept valid: libpng itself must refuse it.
inline Bytes withIhdrByte(Bytes image, std::size_t at, unsigned char value) {
  image[16 + at] = value;
  const std::uint32_t crc = crc32(image.data() + 12, 17);
  for (int i = 0; i < 4; ++i) image[29 + i] = static_cast<unsigned char>(crc >> (24 - 8 * i));
  return image;
}

// The JSON of texturedGlb's model as a .gltf: the triangle in a data: URI, the image at
// `imageUri` (a file beside it, or a data: URI).
inline std::string texturedGltf(const std::string& imageUri, const std::string& factor) {
  return R"({"asset": {"version": "2.0"}, "buffers": [{"uri": "data:application/octet-stream;base64,)" +
         gltf_test_files::base64(gltf_test_files::trianglePositions()) +
         R"(", "byteLength": 36}], "bufferViews": [{"buffer": 0, "byteLength": 36}],
      "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
        "min": [0, 0, -1], "max": [1, 0, 0]}],
      "images": [{"uri": ")" +
         imageUri + R"("}], "textures": [{"source": 0}],
      "materials": [{"name": "painted", "pbrMetallicRoughness": {"baseColorFactor": )" +
         factor + R"(, "baseColorTexture": {"index": 0}}}],
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "material": 0}]}],
      "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}], "scene": 0})";
}

// A GLB: the triangle, `images` in its BIN chunk (one bufferView each) and `materials`
// materials, material m using image m % images.size() as its base colour (2,000 materials
// sharing one image: each was decoded once per material).
inline Bytes sharedTexturesGlb(const std::vector<Bytes>& images, int materials) {
  Bytes bin = gltf_test_files::trianglePositions();  // 36 bytes
  std::string views = R"({"buffer": 0, "byteLength": 36})", imageList, textureList, materialList;
  for (std::size_t i = 0; i < images.size(); ++i) {
    views += R"(, {"buffer": 0, "byteOffset": )" + std::to_string(bin.size()) +
             R"(, "byteLength": )" + std::to_string(images[i].size()) + "}";
    bin.insert(bin.end(), images[i].begin(), images[i].end());
    while (bin.size() % 4 != 0) bin.push_back(0);
    const std::string sep = i == 0 ? "" : ", ";
    imageList +=
        sep + R"({"bufferView": )" + std::to_string(i + 1) + R"(, "mimeType": "image/png"})";
    textureList += sep + R"({"source": )" + std::to_string(i) + "}";
  }
  for (int m = 0; m < materials; ++m) {
    materialList += std::string(m == 0 ? "" : ", ") +
                    R"({"pbrMetallicRoughness": {"baseColorTexture": {"index": )" +
                    std::to_string(std::size_t(m) % images.size()) + "}}}";
  }
  const std::string json = R"({"asset": {"version": "2.0"}, "buffers": [{"byteLength": )" +
                           std::to_string(bin.size()) + R"(}], "bufferViews": [)" + views +
                           R"(], "accessors": [{"bufferView": 0, "componentType": 5126,
      "count": 3, "type": "VEC3", "min": [0, 0, -1], "max": [1, 0, 0]}], "images": [)" +
                           imageList + R"(], "textures": [)" + textureList +
                           R"(], "materials": [)" + materialList + R"(],
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "material": 0}]}],
      "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}], "scene": 0})";
  return gltf_test_files::glb(json, bin);
}

// A GLB: the triangle and `image` in its BIN chunk, a material with baseColorFactor `factor`
// and the image as its baseColorTexture.
inline Bytes texturedGlb(const Bytes& image, const std::string& factor) {
  Bytes bin = gltf_test_files::trianglePositions();  // 36 bytes
  bin.insert(bin.end(), image.begin(), image.end());
  const std::string json = R"({"asset": {"version": "2.0"}, "buffers": [{"byteLength": )" +
                           std::to_string(bin.size()) +
                           R"(}], "bufferViews": [{"buffer": 0, "byteLength": 36},
      {"buffer": 0, "byteOffset": 36, "byteLength": )" +
                           std::to_string(image.size()) + R"(}],
      "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
        "min": [0, 0, -1], "max": [1, 0, 0]}],
      "images": [{"bufferView": 1, "mimeType": "image/png"}], "textures": [{"source": 0}],
      "materials": [{"name": "painted", "pbrMetallicRoughness": {"baseColorFactor": )" +
                           factor + R"(, "baseColorTexture": {"index": 0}}}],
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "material": 0}]}],
      "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}], "scene": 0})";
  return gltf_test_files::glb(json, bin);
}

}  // namespace gltf_texture_files
