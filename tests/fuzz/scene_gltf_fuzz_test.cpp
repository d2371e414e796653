// The glTF loader's fuzz target: seeded mutations of the valid seeds and of
// the whole regression corpus (gltf_hostile_corpus.h: damaged GLBs, broken data: URIs, long
// names, narrowed integers, amplifications in small), for a bounded time, each load held to
// the loader's promises (gltf_mutations.h: one bounded line naming the file, or a usable
// model). ctest runs it under the label "fuzz" for OCEAN_GLTF_FUZZ_SECONDS (default 45);
// mutant i of seed S is the same on every machine, so a failure names both and
// OCEAN_GLTF_FUZZ_SEED=S replays it (how far a run gets depends on the machine's speed).
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "gltf_hostile_corpus.h"
#include "gltf_mutations.h"
#include "gltf_test_files.h"
#include "scene/gltf_loader.h"
#include "scene/hash_noise.h"

namespace ocean_scene {
namespace {

namespace fs = std::filesystem;
namespace corpus = gltf_hostile_corpus;
using gltf_mutations::Bytes;

double envNumber(const char* name, double fallback) {
  const char* text = std::getenv(name);
  return text != nullptr && *text != '\0' ? std::atof(text) : fallback;
}

// One seed: the model's bytes and the case folder holding the files beside it.
struct Seed {
  Bytes model;
  fs::path dir;
  std::string name;
};

// The unit test's seeds and every corpus case but the big ones (a mutant of a 13 MB file
// costs a hundred small ones); the amplifications come in small, still over a lowered budget.
std::vector<Seed> seeds(const fs::path& root) {
  std::vector<Seed> out;
  const fs::path plain = gltf_test_files::freshDir(root, "seeds");
  int n = 0;
  for (const Bytes& b : gltf_mutations::corpus()) {
    out.push_back({b, plain, "seed " + std::to_string(n++)});
  }
  std::vector<corpus::Case> cases = corpus::corpus(root);
  cases.push_back({"small_primitives", "s.gltf", {{"s.gltf", corpus::manyPrimitives(40)}}, "", ""});
  cases.push_back(
      {"small_instances", "s.gltf", {{"s.gltf", corpus::instancedTriangles(3, 20)}}, "", ""});
  cases.push_back({"small_nodes", "s.gltf", {{"s.gltf", corpus::manyNodes(60)}}, "", ""});
  for (const corpus::Case& c : cases) {
    if (c.files.front().second.size() > (256u << 10)) continue;
    corpus::write(root, c);
    out.push_back({c.files.front().second, root / c.name, c.name});
  }
  return out;
}

TEST(SceneGltfFuzzTarget, MutationsOfEverySeedForABoundedTime) {
  const double seconds = envNumber("OCEAN_GLTF_FUZZ_SECONDS", 45.0);
  const auto seed = static_cast<std::uint32_t>(envNumber("OCEAN_GLTF_FUZZ_SEED", 28.0));
  const fs::path root = gltf_test_files::freshDir(fs::path(testing::TempDir()), "ocean_fuzz28");
  const std::vector<Seed> all = seeds(root);
  // Low limits, so that mutated counts cross them often and the budget's arithmetic is fuzzed
  // too (the small amplifications are over them as they are).
  GltfLimits limits;
  limits.triangles = 20000;
  limits.instances = 50;
  limits.nodes = 50;
  limits.bytes = 8u << 20;
  ::alarm(static_cast<unsigned>(seconds) + 120);  // a hang ends the binary, never CI
  const auto start = std::chrono::steady_clock::now();
  int tried = 0, loaded = 0;
  while (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() <
         seconds) {
    const Seed& s = all[std::size_t(tried) % all.size()];
    HashRng rng(hashCombine(seed, std::uint32_t(tried)));
    const Bytes mutant = gltf_mutations::mutate(s.model, rng);
    // Beside the case's own files, so that its URIs still name them.
    const fs::path path = s.dir / ("mutant" + std::to_string(tried % 8));
    gltf_test_files::writeFile(path, mutant);
    Model model;
    std::string error, warnings;
    const bool ok =
        loadGlb(path.string(), model, error, &warnings, (tried & 1) != 0 ? limits : GltfLimits{});
    SCOPED_TRACE("seed " + std::to_string(seed) + " mutant " + std::to_string(tried) + " of " +
                 s.name);
    gltf_mutations::expectKeepsItsWord(path.string(), ok, model, error, warnings);
    if (testing::Test::HasFatalFailure()) return;
    loaded += ok ? 1 : 0;
    ++tried;
  }
  ::alarm(0);
  EXPECT_GT(loaded, 0);
  EXPECT_LT(loaded, tried);
  std::printf("%d mutants of %zu seeds in %.0f s (seed %u): %d loaded, the rest refused\n", tried,
              all.size(), seconds, seed, loaded);
}

}  // namespace
}  // namespace ocean_scene
