// The sample's handling of users' glTF models: the --model placement syntax, the
// fit-and-set-down transform, and the casters the plugin would refuse (or has no room for)
// left out with a warning instead of failing the render.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <scene/seabed.h>

#include "camera.h"
#include "caster_admission.h"
#include "model_limits_option.h"
#include "model_row.h"
#include "model_spec.h"

namespace ocean {
namespace {

double flatSand(double, double) {
  return -10.0;
}
double slopedSand(double x, double z) {
  return -10.0 + 0.1 * x + 0.2 * z;
}

// --model-limits sets the keys it names and leaves the others.
TEST(SampleModelLimits, SetsTheKeysGiven) {
  ocean_scene::GltfLimits limits;
  std::string error;
  ASSERT_TRUE(parseModelLimits("triangles=8M,bytes=2G", limits, error)) << error;
  EXPECT_EQ(limits.triangles, std::uint64_t(8) << 20);
  EXPECT_EQ(limits.bytes, std::uint64_t(2) << 30);
  EXPECT_EQ(limits.instances, ocean_scene::GltfLimits{}.instances);
  EXPECT_EQ(limits.nodes, ocean_scene::GltfLimits{}.nodes);
  ASSERT_TRUE(parseModelLimits("nodes=1099511627776", limits, error)) << error;  // 2^40
  EXPECT_EQ(limits.nodes, std::uint64_t(1) << 40);
  for (const char* bad : {"", "nodes", "nodes=", "nodes=0", "nodes=-1", "nodes=1099511627777",
                          "nodes=1025G", "nodes=3,", "nodes=1.5", "vertices=3"}) {
    EXPECT_FALSE(parseModelLimits(bad, limits, error)) << bad;
    EXPECT_NE(error.find("--model-limits"), std::string::npos) << error;
  }
}

TEST(SampleModelSpec, ParsesFileAloneWithDefaultFit) {
  ModelSpec spec;
  std::string error;
  ASSERT_TRUE(parseModelSpec("models/fox.glb", spec, error)) << error;
  EXPECT_EQ(spec.path, "models/fox.glb");
  EXPECT_FALSE(spec.position.has_value());
  ASSERT_TRUE(spec.fitMetres.has_value());
  EXPECT_EQ(*spec.fitMetres, kDefaultFitMetres);
}

TEST(SampleModelSpec, ParsesPositionAndFit) {
  ModelSpec spec;
  std::string error;
  ASSERT_TRUE(parseModelSpec("C:dir/a.glb@1.5,-2,3e0:fit=0.25", spec, error)) << error;
  EXPECT_EQ(spec.path, "C:dir/a.glb");  // ':' inside the path is kept
  ASSERT_TRUE(spec.position.has_value());
  EXPECT_EQ(*spec.position, glm::dvec3(1.5, -2.0, 3.0));
  EXPECT_EQ(*spec.fitMetres, 0.25);
  ASSERT_TRUE(parseModelSpec("a.glb:fit=none", spec, error)) << error;
  EXPECT_FALSE(spec.fitMetres.has_value());
}

TEST(SampleModelSpec, RefusesMalformedSuffixesWithOneLine) {
  for (const char* bad :
       {"a.glb@1,2", "a.glb@1,2,3,4", "a.glb@x,1,2", "a.glb@1,2,nan", "a.glb@1e9,0,0",
        "a.glb:fit=0", "a.glb:fit=-1", "a.glb:fit=big", "a.glb:fit=1e3", "@1,2,3", ":fit=1"}) {
    SCOPED_TRACE(bad);
    ModelSpec spec;
    std::string error;
    EXPECT_FALSE(parseModelSpec(bad, spec, error));
    EXPECT_EQ(error.rfind(std::string("--model '") + bad + "'", 0), 0u) << error;
    EXPECT_EQ(error.find('\n'), std::string::npos);
  }
}

// A 79 m model is fitted to 1.5 m, centred on (x, z) and its lowest point put on the sand.
TEST(SampleModelSpec, DefaultFitsAndRestsOnTheSand) {
  ModelSpec spec;
  glm::dmat4 m;
  std::string error;
  const glm::dvec3 lo(-10, 5, -20), hi(30, 84, 0);  // 79 m tall, off-centre, floating at y=5
  ASSERT_TRUE(placementTransform(spec, lo, hi, {2.0, 5.0}, &slopedSand, m, error)) << error;
  const glm::dvec3 bottom(m * glm::dvec4(10, 5, -10, 1));  // bottom centre
  const glm::dvec3 top(m * glm::dvec4(10, 84, -10, 1));
  EXPECT_NEAR(bottom.x, 2.0, 1e-9);
  EXPECT_NEAR(bottom.z, 5.0, 1e-9);
  EXPECT_NEAR(bottom.y, slopedSand(2.0, 5.0), 1e-9);
  EXPECT_NEAR(glm::length(top - bottom), kDefaultFitMetres, 1e-9);
}

// The row of models without a position stands in every sea preset's view: each 1.5 m box's
// centre projects inside the camera's frustum (16:9), in front of it, under the water.
TEST(SampleModelRow, EachPresetsCameraSeesTheRow) {
  for (const char* name :
       {"shallow", "seabed", "sunward", "above", "waterline", "torch", "wake", "harbour"}) {
    Preset preset;
    std::string known;
    ASSERT_TRUE(findPreset(name, preset, known)) << name;
    const Camera& camera = preset.camera;
    for (std::size_t count : {std::size_t(1), std::size_t(3)}) {
      for (std::size_t i = 0; i < count; ++i) {
        const glm::dvec3 at = rowPosition(camera, i, count, 1.5, &ocean_scene::seabedHeight);
        const double bottom = ocean_scene::seabedHeight(at.x, at.z) + at.y;
        EXPECT_GE(at.y, 0.0) << name;
        EXPECT_LE(bottom + 1.5, 0.0) << name << ": above the water";
        const glm::dvec3 centre(at.x, bottom + 0.75, at.z);
        const glm::dvec3 local = glm::transpose(camera.rotation()) * (centre - camera.position);
        const glm::dvec4 clip = camera.projection(16.0 / 9.0) * glm::dvec4(local, 1.0);
        ASSERT_GT(clip.w, 0.0) << name << ": behind the camera";
        EXPECT_LT(std::abs(clip.x / clip.w), 0.95) << name << " model " << i << " of " << count;
        EXPECT_LT(std::abs(clip.y / clip.w), 0.95) << name << " model " << i << " of " << count;
      }
    }
  }
}

TEST(SampleModelSpec, ExplicitPositionAndNoFit) {
  ModelSpec spec;
  std::string error;
  ASSERT_TRUE(parseModelSpec("a.glb@4,0.5,-3:fit=none", spec, error));
  glm::dmat4 m;
  const glm::dvec3 lo(-0.05, 0, -0.05), hi(0.05, 0.1, 0.05);  // a 10 cm piece stays 10 cm
  ASSERT_TRUE(placementTransform(spec, lo, hi, {0, 0}, &flatSand, m, error)) << error;
  const glm::dvec3 bottom(m * glm::dvec4(0, 0, 0, 1));
  EXPECT_NEAR(bottom.y, -10.0 + 0.5, 1e-12);
  EXPECT_NEAR(bottom.x, 4.0, 1e-12);
  EXPECT_NEAR(bottom.z, -3.0, 1e-12);
  EXPECT_NEAR(m[1][1], 1.0, 1e-12);
  // A flat point cloud has nothing to fit.
  ModelSpec fit;
  EXPECT_FALSE(placementTransform(fit, lo, lo, {0, 0}, &flatSand, m, error));
}

ocean_scene::Model casterScene(int count, const ocean_scene::Material& material) {
  ocean_scene::Model scene;
  scene.materials.push_back(material);
  ocean_scene::Mesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 0, 1}};
  mesh.normals = {{0, 1, 0}, {0, 1, 0}, {0, 1, 0}};
  mesh.indices = {0, 1, 2};
  scene.meshes.push_back(mesh);
  for (int i = 0; i < count; ++i) {
    scene.instances.push_back({0, glm::mat4(1.0f), "piece" + std::to_string(i)});
  }
  return scene;
}

ocean_scene::Material glass() {
  ocean_scene::Material m;
  m.name = "glass";
  m.transmission = 1.0f;
  m.metallic = 0.0f;  // glTF's default is 1: transmission would not matter on a metal
  return m;
}

TEST(SampleCasterAdmission, AcceptedCastersKeepCasting) {
  ocean_scene::Model scene = casterScene(3, glass());
  std::vector<std::string> warnings;
  admitCasters(scene, warnings);
  EXPECT_TRUE(warnings.empty());
  for (const auto& instance : scene.instances) EXPECT_TRUE(instance.castsCaustics);
}

// Dense attenuation the plugin refuses (absorption > 1e4 /m): that caster is left out and
// named, the rest of the scene still casts.
TEST(SampleCasterAdmission, ExtremeAttenuationLeftOutWithAWarning) {
  ocean_scene::Material dense = glass();
  dense.name = "ink";
  dense.thickness = 0.1f;  // a volume: thin-walled glass has nothing to absorb in
  dense.attenuationColor = glm::vec3(0.01f);
  dense.attenuationDistance = 1e-5f;
  ocean_scene::Model scene = casterScene(2, glass());
  scene.materials.push_back(dense);
  scene.meshes.push_back(scene.meshes[0]);
  scene.meshes[1].material = 1;
  scene.instances[1].mesh = 1;
  scene.instances[1].name = "fox.glb node 'eye'";
  std::vector<std::string> warnings;
  admitCasters(scene, warnings);
  EXPECT_TRUE(scene.instances[0].castsCaustics);
  EXPECT_FALSE(scene.instances[1].castsCaustics);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(
      warnings[0].find("fox.glb node 'eye': casts no caustics, material 'ink' absorbs 4.61e+05 /m"),
      std::string::npos)
      << warnings[0];
  EXPECT_TRUE(casterRefusal(glass(), glm::mat4(1.0f)).empty());
  EXPECT_NE(casterRefusal(glass(), glm::mat4(0.0f)).find("not invertible"), std::string::npos);
}

TEST(SampleCasterAdmission, IorAboveThreeClampedWithAWarning) {
  ocean_scene::Material diamondish = glass();
  diamondish.ior = 4.2f;
  ocean_scene::Model scene = casterScene(2, diamondish);
  std::vector<std::string> warnings;
  admitCasters(scene, warnings);
  EXPECT_TRUE(scene.instances[0].castsCaustics && scene.instances[1].castsCaustics);
  ASSERT_EQ(warnings.size(), 1u);  // once per material, not per instance
  EXPECT_NE(warnings[0].find("material 'glass' ior 4.2 is clamped to 3"), std::string::npos)
      << warnings[0];
  EXPECT_EQ(casterMaterial(diamondish).ior, 3.0f);
}

// More glass and metal than the plugin takes: the first kMaxCasters cast, the rest are drawn
// without caustics, and one warning says how many and from which on.
TEST(SampleCasterAdmission, CasterBudgetIsNeverSilent) {
  ocean_scene::Model scene = casterScene(postfx::kMaxCasters + 5, glass());
  std::vector<std::string> warnings;
  admitCasters(scene, warnings);
  int casting = 0;
  for (const auto& instance : scene.instances) casting += instance.castsCaustics ? 1 : 0;
  EXPECT_EQ(casting, postfx::kMaxCasters);
  EXPECT_FALSE(scene.instances.back().castsCaustics);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("the last 5 (from 'piece64' on)"), std::string::npos) << warnings[0];
}

// The glTF glass fields reach the plugin's material as the spec means them.
TEST(SampleCasterMaterial, GlassFieldsFollowTheGltfSpec) {
  ocean_scene::Material m = glass();
  m.transmission = 0.5f;
  m.metallic = 0.2f;
  m.baseColor = {0.9f, 0.1f, 0.1f};
  m.roughness = 0.3f;
  m.dispersion = 0.4f;
  postfx::CasterMaterial c = casterMaterial(m);
  EXPECT_EQ(c.type, postfx::CasterMaterialType::Refractive);
  EXPECT_FLOAT_EQ(c.transmission, 0.5f * 0.8f);  // transmission acts on the dielectric share
  EXPECT_EQ(c.tint, m.baseColor);
  EXPECT_FLOAT_EQ(c.roughness, 0.3f);
  EXPECT_FLOAT_EQ(c.dispersion, 0.4f);
  EXPECT_TRUE(c.thinWalled);  // no KHR_materials_volume thickness
  EXPECT_EQ(c.absorption, glm::vec3(0.0f));

  // A volume: solid, absorbing per Beer-Lambert (attenuationColor left after the distance).
  m.thickness = 0.05f;
  m.attenuationColor = {0.5f, 0.25f, 1.0f};
  m.attenuationDistance = 2.0f;
  c = casterMaterial(m);
  EXPECT_FALSE(c.thinWalled);
  EXPECT_NEAR(c.absorption.r, std::log(2.0) / 2.0, 1e-6);
  EXPECT_NEAR(c.absorption.g, std::log(4.0) / 2.0, 1e-6);
  EXPECT_NEAR(c.absorption.b, 0.0, 1e-7);

  // Metallic 1 with transmission: glTF's metal lobe takes it all, a mirror of the base colour.
  m.metallic = 1.0f;
  c = casterMaterial(m);
  EXPECT_EQ(c.type, postfx::CasterMaterialType::Reflective);
  EXPECT_EQ(c.reflectance, m.baseColor);

  // KHR_materials_ior 0: an infinite IOR, Fresnel 1: a white mirror, nothing transmitted.
  m.metallic = 0.0f;
  m.ior = 0.0f;
  c = casterMaterial(m);
  EXPECT_EQ(c.type, postfx::CasterMaterialType::Reflective);
  EXPECT_EQ(c.reflectance, glm::vec3(1.0f));
}

TEST(SampleCasterAdmission, DispersionAboveThePluginsLimitClampedWithAWarning) {
  ocean_scene::Material prism = glass();
  prism.dispersion = 25.0f;
  ocean_scene::Model scene = casterScene(1, prism);
  std::vector<std::string> warnings;
  admitCasters(scene, warnings);
  EXPECT_TRUE(scene.instances[0].castsCaustics);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("material 'glass' dispersion 25 is clamped to 10"), std::string::npos)
      << warnings[0];
  EXPECT_EQ(casterMaterial(prism).dispersion, postfx::kMaxCasterDispersion);
}

}  // namespace
}  // namespace ocean
