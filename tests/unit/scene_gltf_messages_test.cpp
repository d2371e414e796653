// Every refusal says what was wrong and where, in a bounded message, and
// nothing a library prints reaches stderr. The files are the regression corpus
// (gltf_hostile_corpus.h): GLB containers damaged field by field, broken data: URIs, 1 MB
// names, paths with "." and "..", integers tinygltf would narrow, meshopt fields, a PNG libpng
// refuses.
#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "gltf_hostile_corpus.h"
#include "gltf_test_files.h"
#include "scene/gltf_loader.h"

namespace ocean_scene {
namespace {

namespace fs = std::filesystem;
namespace corpus = gltf_hostile_corpus;

// The longest run of one repeated character: a value copied whole into a message shows as one.
std::size_t longestRun(const std::string& text) {
  std::size_t best = 0, run = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    run = i > 0 && text[i] == text[i - 1] ? run + 1 : 1;
    best = std::max(best, run);
  }
  return best;
}

struct Outcome {
  bool loaded = false;
  std::string error, warnings, path;
};

Outcome load(const fs::path& path) {
  Outcome o;
  Model model;
  o.path = path.string();
  o.loaded = loadGlb(o.path, model, o.error, &o.warnings);
  return o;
}

class SceneGltfCorpus : public testing::Test {
 protected:
  static void SetUpTestSuite() {
    root_ = gltf_test_files::freshDir(fs::path(testing::TempDir()), "ocean_gltf_corpus");
    cases_ = corpus::corpus(root_);
  }
  static fs::path root_;
  static std::vector<corpus::Case> cases_;
};
fs::path SceneGltfCorpus::root_;
std::vector<corpus::Case> SceneGltfCorpus::cases_;

// Each case refused with its reason (a GLB field by byte offset, a data: URI by reason, a path,
// an integer by its JSON path and exact value), or loaded with the note it should have.
TEST_F(SceneGltfCorpus, EachCaseSaysWhatWasWrongAndWhere) {
  for (const corpus::Case& c : cases_) {
    const Outcome o = load(corpus::write(root_, c));
    if (c.mentions.empty()) {
      EXPECT_TRUE(o.loaded) << c.name << ": " << o.error;
      EXPECT_NE(o.warnings.find(c.notes), std::string::npos) << c.name << ": " << o.warnings;
    } else {
      EXPECT_FALSE(o.loaded) << c.name;
      EXPECT_EQ(o.error.rfind(o.path + ": ", 0), 0u) << c.name << ": " << o.error;
      EXPECT_NE(o.error.find(c.mentions), std::string::npos)
          << c.name << ": '" << c.mentions << "' not in: " << o.error;
    }
    // tinygltf's vague or wrong sentences never come through.
    for (const char* vague :
         {"Invalid glTF binary", "Invalid type for chunk1", "empty BIN chunk", "symbolic link",
          "needs non-negative integer", "-2147483648", "its factors are", "invalid bufferView",
          "not a positive integer", "unexpected end of input", "is 0; it must be",
          "has no node with a mesh"}) {
      const std::string said = o.error + o.warnings;
      EXPECT_EQ(said.find(vague), std::string::npos) << c.name << ": " << said;
    }
  }
}

// No message quotes more than 200 characters of one value (a 1 MB name, a 1 MB data: URI) and
// none is longer than a few hundred characters in all.
TEST_F(SceneGltfCorpus, EveryMessageIsBounded) {
  std::size_t longestError = 0, longestNotes = 0;
  for (const corpus::Case& c : cases_) {
    const Outcome o = load(corpus::write(root_, c));
    const std::string& message = o.loaded ? o.warnings : o.error;
    EXPECT_LE(longestRun(message), 200u) << c.name << ": " << message.substr(0, 400);
    EXPECT_LE(message.size(), o.path.size() + 600) << c.name << ": " << message.substr(0, 800);
    EXPECT_EQ(message.find('\n'), std::string::npos) << c.name;
    EXPECT_TRUE(gltf_test_files::validUtf8(message)) << c.name;
    // OCEAN_GLTF_PRINT=1 shows each message, to read them as a user would.
    if (std::getenv("OCEAN_GLTF_PRINT") != nullptr) {
      std::printf("%s: %s\n", c.name.c_str(), message.c_str());
    }
    if (o.loaded) {
      longestNotes = std::max(longestNotes, message.size());
    } else {
      longestError = std::max(longestError, message.size() - o.path.size());
    }
  }
  std::printf("longest refusal %zu characters after the path, longest notes %zu\n", longestError,
              longestNotes);
}

// What libpng (through OpenImageIO), tinygltf or Draco print is caught and named in the
// loader's own message: nothing reaches the process's stderr.
TEST_F(SceneGltfCorpus, NothingReachesStderr) {
  std::vector<fs::path> paths;
  for (const corpus::Case& c : cases_) paths.push_back(corpus::write(root_, c));
  testing::internal::CaptureStderr();
  for (const fs::path& path : paths) (void)load(path);
  const std::string printed = testing::internal::GetCapturedStderr();
  EXPECT_EQ(printed, "");
}

// A GLB cut at every byte names the field it ended in: the header, the JSON chunk, the BIN
// chunk's header or data, never tinygltf's "Invalid glTF binary.".
TEST(SceneGltfContainer, EveryTruncationNamesItsField) {
  const fs::path d = gltf_test_files::freshDir(fs::path(testing::TempDir()), "ocean_glb_cuts");
  const std::vector<unsigned char> glb = gltf_test_files::triangleGlb();
  for (std::size_t cut = 1; cut < glb.size(); ++cut) {
    const fs::path path = d / ("cut" + std::to_string(cut) + ".glb");
    gltf_test_files::writeFile(path,
                               std::vector<unsigned char>(glb.begin(), glb.begin() + long(cut)));
    const Outcome o = load(path);
    ASSERT_FALSE(o.loaded) << cut;
    const bool named = o.error.find("(byte ") != std::string::npos ||
                       o.error.find("not a glTF file") != std::string::npos ||
                       o.error.find("GLB header cut short") != std::string::npos;
    EXPECT_TRUE(named) << cut << ": " << o.error;
  }
}

}  // namespace
}  // namespace ocean_scene
