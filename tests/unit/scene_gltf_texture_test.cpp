// Base-colour textures: an embedded PNG's mean colour (sRGB-decoded) scales
// the material's base colour; an undecodable or oversized image leaves the factor alone with a
// note. Images are written here through OpenImageIO; nothing is committed.
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "gltf_texture_files.h"
#include "scene/gltf_loader.h"

namespace ocean_scene {
namespace {

namespace fs = std::filesystem;
using namespace gltf_texture_files;

fs::path dir(const std::string& name) {
  return gltf_test_files::freshDir(fs::path(testing::TempDir()) / "ocean_gltf_texture", name);
}

Model load(const fs::path& path, std::string& warnings) {
  Model model;
  std::string error;
  EXPECT_TRUE(loadGlb(path.string(), model, error, &warnings)) << error;
  return model;
}

TEST(SceneGltfTexture, EmbeddedBaseColourTextureMeanScalesTheFactor) {
  const fs::path d = dir("mean");
  const unsigned char orange[3] = {255, 128, 0};
  gltf_test_files::writeFile(d / "painted.glb",
                             texturedGlb(png(d / "orange.png", orange), "[0.5, 1, 1, 1]"));
  std::string warnings;
  const Model model = load(d / "painted.glb", warnings);
  ASSERT_EQ(model.materials.size(), 1u);
  // sRGB 255 -> 1, 128 -> ((128/255 + 0.055) / 1.055)^2.4 = 0.21586, 0 -> 0; times the factor.
  EXPECT_NEAR(model.materials[0].baseColor.r, 0.5f, 1e-5f);
  EXPECT_NEAR(model.materials[0].baseColor.g, 0.21586f, 1e-4f);
  EXPECT_NEAR(model.materials[0].baseColor.b, 0.0f, 1e-6f);
  EXPECT_NE(warnings.find("material 'painted': baseColorTexture averaged into its colour"),
            std::string::npos)
      << warnings;
}

TEST(SceneGltfTexture, UndecodableOrHugeImagesLeaveTheFactor) {
  const fs::path d = dir("hostile");
  const unsigned char grey[3] = {128, 128, 128};
  const Bytes good = png(d / "grey.png", grey);
  const Bytes garbage(64, 0x5a);
  for (const auto& [name, image] :
       {std::pair<std::string, Bytes>{"garbage.glb", garbage},
        std::pair<std::string, Bytes>{"bomb.glb", claimSize(good, 100000, 100000)}}) {
    gltf_test_files::writeFile(d / name, texturedGlb(image, "[0.25, 0.5, 1, 1]"));
    std::string warnings;
    const Model model = load(d / name, warnings);
    ASSERT_EQ(model.materials.size(), 1u) << name;
    EXPECT_EQ(model.materials[0].baseColor, glm::vec3(0.25f, 0.5f, 1.0f)) << name;
    EXPECT_NE(warnings.find("material 'painted': shaded from its factors, without "
                            "baseColorTexture (its image "),
              std::string::npos)
        << name << ": " << warnings;
  }
}

// Found by a user (the Duck was yellow from its .glb, white from its .gltf): the same image
// as a GLB's bufferView, a file beside a .gltf and a data: URI gives the same colour, through
// the same decoder.
TEST(SceneGltfTexture, SameColourFromEveryContainer) {
  const fs::path d = dir("containers");
  const unsigned char orange[3] = {255, 128, 0};
  const Bytes image = png(d / "orange.png", orange);
  gltf_test_files::writeFile(d / "duck.glb", texturedGlb(image, "[0.5, 1, 1, 1]"));
  gltf_test_files::writeFile(d / "duck.png", image);
  gltf_test_files::writeFile(d / "file.gltf", texturedGltf("duck.png", "[0.5, 1, 1, 1]"));
  gltf_test_files::writeFile(
      d / "data.gltf",
      texturedGltf("data:image/png;base64," + gltf_test_files::base64(image), "[0.5, 1, 1, 1]"));
  for (const char* name : {"duck.glb", "file.gltf", "data.gltf"}) {
    std::string warnings;
    const Model model = load(d / name, warnings);
    ASSERT_EQ(model.materials.size(), 1u) << name;
    EXPECT_NEAR(model.materials[0].baseColor.r, 0.5f, 1e-5f) << name;
    EXPECT_NEAR(model.materials[0].baseColor.g, 0.21586f, 1e-4f) << name;
    EXPECT_NEAR(model.materials[0].baseColor.b, 0.0f, 1e-6f) << name;
    EXPECT_NE(warnings.find("baseColorTexture averaged into its colour"), std::string::npos)
        << name << ": " << warnings;
  }
}

// An image file no base colour uses is never opened, and one outside the model's folder is
// not read even when a base colour uses it (the buffers' rule).
TEST(SceneGltfTexture, ImageFilesOutsideTheFolderAreNotRead) {
  const fs::path d = dir("outside");
  fs::create_directories(d / "model");
  const unsigned char orange[3] = {255, 128, 0};
  const Bytes image = png(d / "orange.png", orange);
  fs::create_symlink(d / "orange.png", d / "model" / "link.png");
  for (const auto& [uri, why] :
       {std::pair<std::string, std::string>{"../orange.png", "leaves"},
        std::pair<std::string, std::string>{"link.png", "is a symbolic link"},
        std::pair<std::string, std::string>{"missing.png", "names no"}}) {
    gltf_test_files::writeFile(d / "model" / "t.gltf", texturedGltf(uri, "[1, 1, 1, 1]"));
    std::string warnings;
    const Model model = load(d / "model" / "t.gltf", warnings);
    ASSERT_EQ(model.materials.size(), 1u);
    EXPECT_EQ(model.materials[0].baseColor, glm::vec3(1.0f)) << uri;
    EXPECT_NE(warnings.find("without baseColorTexture (its file '" + uri + "' " + why),
              std::string::npos)
        << warnings;
  }
}

}  // namespace
}  // namespace ocean_scene
