// A deterministic mutation fuzz of the glTF loader: small valid files,
// generated here, are damaged in thousands of seeded ways (byte flips, truncation, spliced and
// deleted runs, hostile numbers and brackets in the JSON, GLB length fields). Every load must
// return, with either one line of valid UTF-8 naming the file, or a model that keeps the
// loader's promises. A crash ends the binary, a hang trips the alarm; both fail in ctest.
#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "gltf_mutations.h"
#include "gltf_test_files.h"
#include "scene/gltf_loader.h"
#include "scene/hash_noise.h"

namespace ocean_scene {
namespace {

namespace fs = std::filesystem;
using gltf_mutations::Bytes;
using gltf_mutations::corpus;
using gltf_mutations::expectUsable;
using gltf_mutations::mutate;

TEST(SceneGltfFuzz, SeededMutationsNeverCrashHangOrMisreport) {
  const fs::path dir = gltf_test_files::freshDir(fs::path(testing::TempDir()), "ocean_gltf_fuzz");
  const std::vector<Bytes> seeds = corpus();
  // Each seed must load, or the mutants would test only the first check.
  for (std::size_t s = 0; s < seeds.size(); ++s) {
    const fs::path path = dir / ("seed" + std::to_string(s));
    gltf_test_files::writeFile(path, seeds[s]);
    Model model;
    std::string error;
    ASSERT_TRUE(loadGlb(path.string(), model, error)) << error;
  }
  ::alarm(120);  // a hang ends the binary (SIGALRM) instead of stalling CI
  HashRng rng(17);
  constexpr int kMutants = 1500;  // about 2 s on one core
  int loaded = 0;
  for (int i = 0; i < kMutants; ++i) {
    const Bytes mutant = mutate(seeds[std::size_t(i) % seeds.size()], rng);
    const fs::path path = dir / ("m" + std::to_string(i % 16));
    gltf_test_files::writeFile(path, mutant);
    Model model;
    std::string error, warnings;
    const bool ok = loadGlb(path.string(), model, error, &warnings);
    SCOPED_TRACE("mutant " + std::to_string(i));
    if (ok) ++loaded;
    gltf_mutations::expectKeepsItsWord(path.string(), ok, model, error, warnings);
    if (testing::Test::HasFatalFailure()) return;
  }
  ::alarm(0);
  // Both outcomes occur: a mutator that broke every file (or none) would test too little.
  EXPECT_GT(loaded, 0);
  EXPECT_LT(loaded, kMutants);
  std::printf("%d of %d mutants loaded, the rest refused with one line\n", loaded, kMutants);
}

}  // namespace
}  // namespace ocean_scene
