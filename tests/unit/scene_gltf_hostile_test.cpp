// The glTF loader against files built to hurt it: each is refused with one line
// of valid UTF-8 naming the file and the reason, without crashing, blocking, or reading
// anything outside the model's own folder. All files are generated here.
#include <sys/stat.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "gltf_test_files.h"
#include "gltf_texture_files.h"
#include "scene/gltf_loader.h"

namespace ocean_scene {
namespace {

namespace fs = std::filesystem;
using gltf_test_files::TriangleJson;
using gltf_test_files::writeFile;

fs::path root() {
  return fs::path(testing::TempDir()) / "ocean_gltf_hostile";
}

fs::path dir(const std::string& name) {
  return gltf_test_files::freshDir(root(), name);
}

// A hang is a failure: SIGALRM's default action ends the test binary, which ctest reports.
struct HangGuard {
  HangGuard() { ::alarm(20); }
  ~HangGuard() { ::alarm(0); }
};

std::string refused(const fs::path& path) {
  HangGuard guard;
  Model model;
  std::string error;
  EXPECT_FALSE(loadGlb(path.string(), model, error));
  EXPECT_TRUE(model.instances.empty() && model.meshes.empty());
  EXPECT_EQ(error.rfind(path.string() + ": ", 0), 0u) << error;
  EXPECT_EQ(error.find('\n'), std::string::npos) << error;
  EXPECT_TRUE(gltf_test_files::validUtf8(error)) << error;
  return error;
}

Model loaded(const fs::path& path, std::string* warnings = nullptr) {
  HangGuard guard;
  Model model;
  std::string error;
  EXPECT_TRUE(loadGlb(path.string(), model, error, warnings)) << error;
  return model;
}

#define EXPECT_MENTIONS(text, word) \
  EXPECT_NE((text).find(word), std::string::npos) << "'" << (word) << "' not in: " << (text)

// A file that loads, to prove the refusals below come from the hostile part alone.
TEST(SceneGltfHostile, BaselineTriangleLoadsAsGltfAndGlb) {
  const fs::path d = dir("baseline");
  writeFile(d / "t.gltf", TriangleJson{}.text());
  writeFile(d / "t.glb", gltf_test_files::triangleGlb());
  EXPECT_EQ(loaded(d / "t.gltf").instances.size(), 1u);
  EXPECT_EQ(loaded(d / "t.glb").instances.size(), 1u);
}

// 20,000 nested arrays in extras used to overflow the stack in tinygltf's recursive parse.
TEST(SceneGltfHostile, DeepNestingRefusedBeforeParse) {
  const fs::path d = dir("deep");
  TriangleJson deep;
  deep.top = "\"extras\": " + std::string(20000, '[') + std::string(20000, ']') + ", ";
  writeFile(d / "extras.glb", gltf_test_files::triangleGlb(deep));
  EXPECT_MENTIONS(refused(d / "extras.glb"), "nests deeper than 64");
  TriangleJson objects;
  std::string nest;
  for (int i = 0; i < 100000; ++i) nest += "{\"a\":";
  objects.top = "\"extensions\": " + nest + "1" + std::string(100000, '}') + ", ";
  writeFile(d / "extensions.gltf", objects.text());
  EXPECT_MENTIONS(refused(d / "extensions.gltf"), "nests deeper than 64");
  // Brackets inside strings do not count, and modest extras still load.
  TriangleJson modest;
  modest.top = "\"extras\": {\"s\": \"" + std::string(500, '[') +
               "\", \"d\": " + std::string(40, '[') + std::string(40, ']') + "}, ";
  writeFile(d / "modest.gltf", modest.text());
  EXPECT_EQ(loaded(d / "modest.gltf").instances.size(), 1u);
}

TEST(SceneGltfHostile, ModelPathMustBeARegularFile) {
  const fs::path d = dir("kinds");
  EXPECT_MENTIONS(refused(d), "is a directory");
  ASSERT_EQ(::mkfifo((d / "pipe.glb").c_str(), 0600), 0);
  EXPECT_MENTIONS(refused(d / "pipe.glb"), "FIFO");
  EXPECT_MENTIONS(refused("/dev/zero"), "is a device");
  EXPECT_MENTIONS(refused(d / "missing.glb"), "cannot open");
}

TEST(SceneGltfHostile, FifoBufferRefusedWithoutBlocking) {
  const fs::path d = dir("fifo_buffer");
  ASSERT_EQ(::mkfifo((d / "pipe.bin").c_str(), 0600), 0);
  TriangleJson json;
  json.buffer = "\"uri\": \"pipe.bin\"";
  writeFile(d / "t.gltf", json.text());
  EXPECT_MENTIONS(refused(d / "t.gltf"), "buffer 0 uri 'pipe.bin' is a FIFO");
}

// Images are not used: a FIFO, a missing file or a path outside the folder as an image URI is
// never opened, and the model loads with a note saying so.
TEST(SceneGltfHostile, ImageUrisAreNeverOpened) {
  const fs::path d = dir("fifo_image");
  ASSERT_EQ(::mkfifo((d / "pipe.png").c_str(), 0600), 0);
  TriangleJson json;
  json.top = "\"images\": [{\"uri\": \"pipe.png\"}, {\"uri\": \"../../../../etc/passwd\"}], ";
  writeFile(d / "t.gltf", json.text());
  std::string warnings;
  EXPECT_EQ(loaded(d / "t.gltf", &warnings).instances.size(), 1u);
  EXPECT_MENTIONS(warnings, "2 image file(s) not read");
  EXPECT_EQ(warnings.find("File not found"), std::string::npos) << warnings;
}

TEST(SceneGltfHostile, BufferUrisStayInsideTheModelsFolder) {
  const fs::path d = dir("escape");
  fs::create_directories(d / "model");
  // A foreign file of a size that differs from byteLength: its size must never be printed.
  writeFile(d / "secret.bin", std::string(1234, 'x'));
  const auto attempt = [&](const std::string& uri) {
    TriangleJson json;
    json.buffer = "\"uri\": \"" + uri + "\"";
    writeFile(d / "model" / "t.gltf", json.text());
    const std::string error = refused(d / "model" / "t.gltf");
    EXPECT_EQ(error.find("1234"), std::string::npos) << error;
    return error;
  };
  EXPECT_MENTIONS(attempt("../secret.bin"), "leaves the model's folder");
  EXPECT_MENTIONS(attempt("%2e%2e/secret.bin"), "leaves the model's folder");
  EXPECT_MENTIONS(attempt("sub/../../secret.bin"), "leaves the model's folder");
  EXPECT_MENTIONS(attempt((d / "secret.bin").string()), "is an absolute path");
  EXPECT_MENTIONS(attempt("/etc/passwd"), "is an absolute path");
  EXPECT_MENTIONS(attempt("file:///etc/passwd"), "scheme (file:)");
  EXPECT_MENTIONS(attempt("file:../secret.bin"), "scheme (file:)");
  EXPECT_MENTIONS(attempt("http://example.com/a.bin"), "scheme (http:)");
  fs::create_symlink(d / "secret.bin", d / "model" / "link.bin");
  EXPECT_MENTIONS(attempt("link.bin"), "symbolic link that leads out");
  fs::create_directories(d / "model" / "folder.bin");
  EXPECT_MENTIONS(attempt("folder.bin"), "is a directory");
}

// tinygltf also looked in the working directory; only the model's folder is searched now.
TEST(SceneGltfHostile, BufferIsNotSearchedInTheWorkingDirectory) {
  const fs::path d = dir("cwd");
  fs::create_directories(d / "model");
  writeFile(d / "only_here.bin", gltf_test_files::trianglePositions());
  TriangleJson json;
  json.buffer = "\"uri\": \"only_here.bin\"";
  writeFile(d / "model" / "t.gltf", json.text());
  const fs::path before = fs::current_path();
  fs::current_path(d);
  const std::string error = refused(d / "model" / "t.gltf");
  fs::current_path(before);
  EXPECT_MENTIONS(error, "names no file in the model's folder");
  // The same buffer next to the model loads.
  writeFile(d / "model" / "only_here.bin", gltf_test_files::trianglePositions());
  EXPECT_EQ(loaded(d / "model" / "t.gltf").instances.size(), 1u);
}

TEST(SceneGltfHostile, ComposedTransformsCheckedAfterFloatConversion) {
  const fs::path d = dir("transforms");
  const auto withNodes = [&](const std::string& name, const std::string& nodes) {
    TriangleJson json;
    json.nodes = nodes;
    writeFile(d / name, json.text());
    return d / name;
  };
  EXPECT_MENTIONS(
      refused(withNodes("huge_scale.gltf", R"({"mesh": 0, "scale": [1e30, 1e30, 1e30]})")),
      "beyond 1000000 m");
  // 1e39 is a finite double but not a finite float.
  EXPECT_MENTIONS(refused(withNodes("far.gltf", R"({"mesh": 0, "translation": [1e39, 0, 0]})")),
                  "overflows float");
  // Each node's own scale is fine; their product is not.
  const std::string chain = R"({"children": [1], "scale": [1e20, 1e20, 1e20]},
      {"children": [2], "scale": [1e20, 1e20, 1e20]}, {"mesh": 0})";
  EXPECT_MENTIONS(refused(withNodes("chain.gltf", chain)),
                  "node 2: its composed transform overflows");
  EXPECT_MENTIONS(
      refused(withNodes("projective.gltf",
                        R"({"mesh": 0, "matrix": [1,0,0,0.5, 0,1,0,0, 0,0,1,0, 0,0,0,1]})")),
      "projective");
}

TEST(SceneGltfHostile, NegativeOffsetsAndSizesRefused) {
  const fs::path d = dir("negative");
  TriangleJson accessor;
  accessor.accessor = "\"byteOffset\": -4";
  writeFile(d / "accessor.gltf", accessor.text());
  EXPECT_MENTIONS(refused(d / "accessor.gltf"), "accessors[0].byteOffset is -4");
  std::string view = TriangleJson{}.text();
  view.replace(view.find("\"byteLength\": 36}], \"accessors\""), 16, "\"byteLength\": -36");
  writeFile(d / "view.gltf", view);
  EXPECT_MENTIONS(refused(d / "view.gltf"), "bufferViews[0].byteLength is -36");
  TriangleJson fraction;
  fraction.accessor = "\"byteOffset\": 0.5";
  writeFile(d / "fraction.gltf", fraction.text());
  EXPECT_MENTIONS(refused(d / "fraction.gltf"), "must be a non-negative integer");
}

// One rule for every index: an integer >= 0 written as one. tinygltf read a negative index as
// "none" and -0 as 0, and the work budget counted neither, so "mesh": -0 drew mesh 0 uncounted.
// Each refusal names the field by its JSON path, the value as written and what it indexes.
TEST(SceneGltfHostile, EveryIndexIsAnIntegerAtLeastZero) {
  const fs::path d = dir("indices");
  const std::string rich = [] {
    const auto b = gltf_test_files::featureRichModel(false);
    return std::string(b.begin(), b.end());
  }();
  const std::string textured = gltf_texture_files::texturedGltf("t.png", "[1, 1, 1, 1]");
  TriangleJson extra;
  extra.nodes = "{\"mesh\": 0, \"children\": [1], \"camera\": 0}, {\"skin\": 0}";
  extra.top =
      "\"skins\": [{\"joints\": [1], \"inverseBindMatrices\": 0}], \"animations\": "
      "[{\"channels\": [{\"sampler\": 0, \"target\": {\"node\": 1, \"path\": "
      "\"scale\"}}], \"samplers\": [{\"input\": 0, \"output\": 0}]}], ";
  const std::string triangle = extra.text();
  struct Field {
    const std::string* text;
    std::string from, to, path, indexes;
  };
  const Field fields[] = {
      {&rich, "\"scene\": 0", "\"scene\": -0", "scene", "scenes"},
      {&rich, "\"nodes\": [0]}]", "\"nodes\": [-0]}]", "scenes[0].nodes[0]", "nodes"},
      {&rich, "{\"mesh\": 0", "{\"mesh\": -1", "nodes[0].mesh", "meshes"},
      {&rich, "\"TRANSLATION\": 2", "\"TRANSLATION\": -0",
       "nodes[0].extensions.EXT_mesh_gpu_instancing.attributes.TRANSLATION", "accessors"},
      {&rich, "\"NORMAL\": 1", "\"NORMAL\": -1", "meshes[0].primitives[0].attributes.NORMAL",
       "accessors"},
      {&rich, "\"indices\": {\"bufferView\": 2", "\"indices\": {\"bufferView\": -0",
       "accessors[0].sparse.indices.bufferView", "bufferViews"},
      {&rich, "\"values\": {\"bufferView\": 3", "\"values\": {\"bufferView\": 3.0",
       "accessors[0].sparse.values.bufferView", "bufferViews"},
      {&rich, "{\"bufferView\": 1,", "{\"bufferView\": -0,", "accessors[1].bufferView",
       "bufferViews"},
      {&rich, "{\"buffer\": 0, \"byteLength\": 48}", "{\"buffer\": -0, \"byteLength\": 48}",
       "bufferViews[0].buffer", "buffers"},
      {&textured, "{\"source\": 0}", "{\"source\": -0, \"sampler\": 0}", "textures[0].source",
       "images"},
      {&textured, "{\"source\": 0}", "{\"source\": 0, \"sampler\": -2}", "textures[0].sampler",
       "samplers"},
      {&textured, "{\"index\": 0}", "{\"index\": -0}",
       "materials[0].pbrMetallicRoughness.baseColorTexture.index", "textures"},
      {&textured, "\"material\": 0}", "\"material\": -0}", "meshes[0].primitives[0].material",
       "materials"},
      {&triangle, "\"children\": [1]", "\"children\": [-0]", "nodes[0].children[0]", "nodes"},
      {&triangle, "\"camera\": 0", "\"camera\": -1", "nodes[0].camera", "cameras"},
      {&triangle, "{\"skin\": 0}", "{\"skin\": \"0\"}", "nodes[1].skin", "skins"},
      {&triangle, "\"joints\": [1]", "\"joints\": [-0]", "skins[0].joints[0]", "nodes"},
      {&triangle, "\"inverseBindMatrices\": 0", "\"inverseBindMatrices\": -0",
       "skins[0].inverseBindMatrices", "accessors"},
      {&triangle, "\"node\": 1", "\"node\": -0", "animations[0].channels[0].target.node", "nodes"},
      {&triangle, "\"output\": 0", "\"output\": -3", "animations[0].samplers[0].output",
       "accessors"},
  };
  int n = 0;
  for (const Field& f : fields) {
    std::string text = *f.text;
    const std::size_t at = text.find(f.from);
    ASSERT_NE(at, std::string::npos) << f.from;
    text.replace(at, f.from.size(), f.to);
    const fs::path path = d / ("index" + std::to_string(n++) + ".gltf");
    writeFile(path, text);
    const std::string error = refused(path);
    EXPECT_MENTIONS(error, f.path + " is ");
    EXPECT_MENTIONS(error, "; an index must be an integer >= 0 (the position of an entry of \"" +
                               f.indexes + "\")");
  }
  // The original files load: the rule refuses only what breaks it.
  TriangleJson plain;
  plain.nodes = "{\"mesh\": 0, \"children\": [1]}, {\"mesh\": 0}";
  writeFile(d / "plain.gltf", plain.text());
  EXPECT_EQ(loaded(d / "plain.gltf").instances.size(), 2u);
}

TEST(SceneGltfHostile, PositionsOutsideMinMaxRefused) {
  const fs::path d = dir("bounds");
  TriangleJson json;
  json.accessor = "\"min\": [0, 0, -1], \"max\": [0.5, 0, 0]";  // x reaches 1
  writeFile(d / "spike.gltf", json.text());
  EXPECT_MENTIONS(refused(d / "spike.gltf"), "outside the accessor's min/max");
  json.accessor = "\"min\": [0, 0, -1.000001], \"max\": [1.000001, 0, 0]";  // decimal rounding
  writeFile(d / "rounded.gltf", json.text());
  std::string warnings;
  EXPECT_EQ(loaded(d / "rounded.gltf", &warnings).instances.size(), 1u);
  EXPECT_EQ(warnings.find("min/max"), std::string::npos) << warnings;
  // Bounds are required by the spec; a file without them loads with a note saying so.
  json.accessor = "";
  writeFile(d / "unbounded.gltf", json.text());
  EXPECT_EQ(loaded(d / "unbounded.gltf", &warnings).instances.size(), 1u);
  EXPECT_MENTIONS(warnings, "POSITION accessor 0 has no min/max");
}

TEST(SceneGltfHostile, RequiredExtensionsRefusedByName) {
  const fs::path d = dir("extensions");
  const auto requiring = [&](const std::string& name) {
    TriangleJson json;
    json.top =
        "\"extensionsUsed\": [\"" + name + "\"], \"extensionsRequired\": [\"" + name + "\"], ";
    writeFile(d / (name + ".gltf"), json.text());
    return d / (name + ".gltf");
  };
  EXPECT_MENTIONS(refused(requiring("EXT_made_up")), "extension EXT_made_up is required");
  EXPECT_MENTIONS(refused(requiring("KHR_meshopt_compression")), "meshopt");
  // Decoded (scene_gltf_draco_test.cpp, scene_gltf_meshopt_test.cpp): required is fine.
  EXPECT_EQ(loaded(requiring("KHR_draco_mesh_compression")).instances.size(), 1u);
  EXPECT_EQ(loaded(requiring("EXT_meshopt_compression")).instances.size(), 1u);
  EXPECT_EQ(loaded(requiring("KHR_materials_transmission")).instances.size(), 1u);
}

// A Draco primitive whose bufferView holds no Draco data (here: raw floats) is refused by
// name; real Draco files load (scene_gltf_draco_test.cpp).
TEST(SceneGltfHostile, DracoGarbageRefusedByName) {
  const fs::path d = dir("draco");
  TriangleJson json;
  json.top = "\"extensionsUsed\": [\"KHR_draco_mesh_compression\"], ";
  json.primitive =
      R"("extensions": {"KHR_draco_mesh_compression": {"bufferView": 0, "attributes": {"POSITION": 0}}})";
  std::string text = json.text();
  text.replace(text.find("{\"bufferView\": 0, \"componentType\""), 17, "{");
  writeFile(d / "draco.gltf", text);
  EXPECT_MENTIONS(refused(d / "draco.gltf"),
                  "KHR_draco_mesh_compression data could not be decoded");
}

TEST(SceneGltfHostile, ParseErrorsNeverEchoRawBytes) {
  const fs::path d = dir("utf8");
  std::string text = TriangleJson{}.text();
  text.insert(text.find("\"asset\""), "\xff\xfe\x01garbage");
  writeFile(d / "bad.gltf", text);
  const std::string error = refused(d / "bad.gltf");
  EXPECT_EQ(error.find('\xff'), std::string::npos);
  // Names can carry invalid UTF-8 too; any message quoting them is escaped.
  TriangleJson name;
  name.nodes = "{\"mesh\": 0, \"name\": \"n\xc3\", \"translation\": [1e39, 0, 0]}";
  writeFile(d / "name.gltf", name.text());
  refused(d / "name.gltf");
}

}  // namespace
}  // namespace ocean_scene
