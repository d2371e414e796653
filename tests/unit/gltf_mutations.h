#pragma once
// The glTF loader's seeded mutation fuzz, shared by the unit test (a fixed 1500 mutants) and
// the fuzz target that runs for a bounded time (tests/fuzz/scene_gltf_fuzz_test.cpp): the
// valid seeds, the mutator, and what a successful load promises.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "gltf_compressed_files.h"
#include "gltf_test_files.h"
#include "gltf_texture_files.h"
#include "scene/gltf_loader.h"
#include "scene/hash_noise.h"

namespace gltf_mutations {

namespace fs = std::filesystem;
using gltf_test_files::TriangleJson;
using Bytes = std::vector<unsigned char>;
using ocean_scene::HashRng;
using ocean_scene::Instance;
using ocean_scene::Mesh;
using ocean_scene::Model;

inline Bytes bytesOf(const std::string& text) {
  return Bytes(text.begin(), text.end());
}

// Valid seeds covering the loader's paths, each as text and binary: a plain triangle; a strip
// under a node hierarchy with glass materials; sparse positions, quantized normals and GPU
// instancing; then a Draco quad (text), a meshopt quad and a textured triangle (binary).
inline std::vector<Bytes> corpus() {
  std::vector<Bytes> seeds;
  TriangleJson plain;
  seeds.push_back(bytesOf(plain.text()));
  seeds.push_back(gltf_test_files::triangleGlb(plain));
  TriangleJson strip;
  strip.data = gltf_test_files::bytesOf({0, 0, 0, 1, 0, 0, 0, 0, -1, 1, 0, -1});
  strip.count = 4;
  strip.primitive = "\"mode\": 5, \"material\": 0";
  strip.accessor = "\"min\": [0, 0, -1], \"max\": [1, 0, 0]";
  strip.top =
      "\"materials\": [{\"name\": \"glass\", \"extensions\": {\"KHR_materials_transmission\": "
      "{\"transmissionFactor\": 1}, \"KHR_materials_ior\": {\"ior\": 1.5}, "
      "\"KHR_materials_volume\": {\"thicknessFactor\": 0.1, \"attenuationDistance\": 2, "
      "\"attenuationColor\": [1, 0.5, 0.5]}}}], \"extensionsUsed\": "
      "[\"KHR_materials_transmission\", \"KHR_materials_ior\", \"KHR_materials_volume\"], ";
  strip.nodes =
      "{\"children\": [1], \"translation\": [0, 1, 0], \"rotation\": [0, 0.7071, 0, 0.7071]}, "
      "{\"mesh\": 0, \"scale\": [2, 2, 2]}";
  seeds.push_back(bytesOf(strip.text()));
  seeds.push_back(gltf_test_files::triangleGlb(strip));
  seeds.push_back(gltf_test_files::featureRichModel(false));
  seeds.push_back(gltf_test_files::featureRichModel(true));
  // Compressed geometry: the mutations reach libdraco's and libmeshoptimizer's decoders.
  using namespace gltf_compressed_files;
  const DracoQuad draco = encodeDracoQuad();
  seeds.push_back(bytesOf(dracoGltf(draco, draco.points, kBounds)));
  const Compressed meshopt = encodeMeshoptQuad();
  seeds.push_back(gltf_test_files::glb(meshoptGltf(meshopt, ""), meshopt.bytes));
  // An embedded PNG: the mutations reach OpenImageIO's decoder.
  const unsigned char orange[3] = {255, 128, 0};
  const fs::path image = fs::path(testing::TempDir()) / "ocean_gltf_fuzz_seed.png";
  seeds.push_back(
      gltf_texture_files::texturedGlb(gltf_texture_files::png(image, orange), "[1, 1, 1, 1]"));
  return seeds;
}

inline const std::vector<std::string> kHostileNumbers = {
    "-1",    "-4",         "0",          "1e39",
    "-1e39", "4294967295", "4294967296", "18446744073709551615",
    "1e308", "0.5",        "2147483647", "-2147483648",
    "65535", "3"};

// One seeded mutation of `seed`.
inline Bytes mutate(const Bytes& seed, HashRng& rng) {
  Bytes out = seed;
  const auto pick = [&](std::size_t n) { return n == 0 ? 0 : std::size_t(rng.nextU32() % n); };
  const int rounds = 1 + int(rng.nextU32() % 3);
  for (int r = 0; r < rounds && !out.empty(); ++r) {
    switch (rng.nextU32() % 7) {
      case 0:  // byte flip
        out[pick(out.size())] = static_cast<unsigned char>(rng.nextU32());
        break;
      case 1:  // truncation
        out.resize(pick(out.size()));
        break;
      case 2: {  // duplicate a run
        const std::size_t at = pick(out.size()),
                          length = pick(std::min<std::size_t>(64, out.size() - at));
        const Bytes run(out.begin() + long(at), out.begin() + long(at + length));
        out.insert(out.begin() + long(pick(out.size())), run.begin(), run.end());
        break;
      }
      case 3: {  // delete a run
        const std::size_t at = pick(out.size()),
                          length = pick(std::min<std::size_t>(32, out.size() - at));
        out.erase(out.begin() + long(at), out.begin() + long(at + length));
        break;
      }
      case 4: {  // a number in the JSON becomes a hostile one
        std::vector<std::size_t> starts;
        for (std::size_t i = 1; i < out.size(); ++i) {
          const bool digit = (out[i] >= '0' && out[i] <= '9') || out[i] == '-';
          const bool before = out[i - 1] == ' ' || out[i - 1] == '[' || out[i - 1] == ':';
          if (digit && before) starts.push_back(i);
        }
        if (starts.empty()) break;
        const std::size_t at = starts[pick(starts.size())];
        std::size_t end = at;
        while (end < out.size() &&
               (std::isdigit(out[end]) || out[end] == '-' || out[end] == '.' || out[end] == 'e'))
          ++end;
        const std::string& number = kHostileNumbers[pick(kHostileNumbers.size())];
        out.erase(out.begin() + long(at), out.begin() + long(end));
        out.insert(out.begin() + long(at), number.begin(), number.end());
        break;
      }
      case 5: {  // brackets: deep nesting or unbalanced
        const std::string brackets(1 + pick(200), rng.nextU32() % 2 ? '[' : '{');
        out.insert(out.begin() + long(pick(out.size())), brackets.begin(), brackets.end());
        break;
      }
      case 6: {  // a GLB length field (total or JSON chunk) set to a nearby or huge value
        if (out.size() < 20 || out[0] != 'g') break;
        const std::size_t field = rng.nextU32() % 2 ? 8 : 12;
        const std::uint32_t value =
            rng.nextU32() % 2 ? rng.nextU32() : std::uint32_t(out.size() - pick(8));
        for (int k = 0; k < 4; ++k)
          out[field + std::size_t(k)] = static_cast<unsigned char>(value >> (8 * k));
        break;
      }
    }
  }
  return out;
}

// What a successful load promises its users (the renderer indexes with these blindly).
inline void expectUsable(const Model& model) {
  ASSERT_FALSE(model.instances.empty());
  for (const Instance& instance : model.instances) {
    ASSERT_LT(instance.mesh, model.meshes.size());
    for (int c = 0; c < 4; ++c) {
      for (int r = 0; r < 4; ++r) ASSERT_TRUE(std::isfinite(instance.transform[c][r]));
    }
  }
  for (const Mesh& mesh : model.meshes) {
    ASSERT_LT(mesh.material, model.materials.size());
    ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
    ASSERT_EQ(mesh.indices.size() % 3, 0u);
    for (std::uint32_t index : mesh.indices) ASSERT_LT(index, mesh.positions.size());
    for (const glm::vec3& p : mesh.positions) {
      ASSERT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
    }
  }
}

// The loader's bounds on its messages (gltf_text.h): 1000 characters after the path for a
// refusal, 4000 for the notes, each plus the "... (N bytes)" that says where it was cut.
inline constexpr std::size_t kMaxRefusal = 1000 + 24, kMaxNotes = 4000 + 24;

// What every load promises, whatever the file: a refusal is one bounded line of valid UTF-8
// naming the file and leaves the model empty; a load keeps expectUsable's promises and its
// notes are one bounded line too.
inline void expectKeepsItsWord(const std::string& path, bool ok, const Model& model,
                               const std::string& error, const std::string& warnings) {
  if (ok) {
    expectUsable(model);
    ASSERT_EQ(warnings.find('\n'), std::string::npos);
    ASSERT_LE(warnings.size(), kMaxNotes);
    ASSERT_TRUE(gltf_test_files::validUtf8(warnings));
  } else {
    ASSERT_TRUE(model.instances.empty() && model.meshes.empty() && model.materials.empty());
    ASSERT_EQ(error.rfind(path + ": ", 0), 0u) << error;
    ASSERT_EQ(error.find('\n'), std::string::npos) << error;
    ASSERT_LE(error.size(), path.size() + 2 + kMaxRefusal) << error.substr(0, 300);
    ASSERT_TRUE(gltf_test_files::validUtf8(error)) << error;
  }
}

}  // namespace gltf_mutations
