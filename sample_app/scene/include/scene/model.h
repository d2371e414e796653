#pragma once
// Scene data model shared by the procedural scene, the glTF loader and the glTF writer.
// Conventions: metres, y up, right-handed; the water surface is the plane y = 0, so
// everything underwater has y < 0. Colours are linear (not sRGB).

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace ocean_scene {

// One triangle list with one material. Positions are in the mesh's own space; an Instance
// places it in the scene. Triangles are counter-clockwise seen from the side the normals
// point to.
struct Mesh {
  std::string name;
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;  // unit length, one per position
  std::vector<std::uint32_t> indices;
  std::uint32_t material = 0;  // index into Model::materials
};

// glTF 2.0 metallic-roughness plus the glass extensions the object-caustics pass needs.
// Defaults are the glTF defaults, so a field a file does not set keeps its spec value.
struct Material {
  std::string name;
  glm::vec3 baseColor{1.0f};  // linear albedo (baseColorFactor.rgb)
  float alpha = 1.0f;         // baseColorFactor.a
  float metallic = 1.0f;      // glTF default is fully metallic
  float roughness = 1.0f;
  bool doubleSided = false;
  // KHR_materials_ior. 0 is the spec's special value: an infinite IOR, Fresnel 1 (all light
  // reflected, none transmitted).
  float ior = 1.5f;
  // KHR_materials_transmission: 0 = opaque, 1 = all non-reflected light is transmitted.
  float transmission = 0.0f;
  // KHR_materials_volume: thickness in mesh-space metres (0 = thin-walled), and Beer-Lambert
  // absorption: light keeps attenuationColor after travelling attenuationDistance metres.
  float thickness = 0.0f;
  glm::vec3 attenuationColor{1.0f};
  float attenuationDistance = std::numeric_limits<float>::infinity();
  // KHR_materials_dispersion: 20 / Abbe number, >= 0 (0: none).
  float dispersion = 0.0f;
  // The procedural scene's rock and stone: the renderer paints them with world-space noise
  // (colour, weed, bumps) instead of a texture. Not part of glTF: a loaded material has false,
  // and the glTF writer leaves it out.
  bool proceduralRock = false;
  // A tiled surface (the pool's tiles, the deck's slabs): the renderer darkens the joints of a
  // grid of this pitch (m, 0: none) fixed to the world on the surface's dominant plane, each
  // joint tileJoint wide (m), filtered over the pixel so that joints finer than a pixel shade it
  // by their share instead of aliasing. Not part of glTF, like proceduralRock.
  float tilePitch = 0.0f;
  float tileJoint = 0.0f;

  bool isRefractive() const { return transmission > 0.0f; }
};

// A mesh placed in the scene (scene space = world: metres, y up, water at y = 0).
struct Instance {
  std::uint32_t mesh = 0;  // index into Model::meshes
  glm::mat4 transform{1.0f};
  std::string name;
  // False: drawn, but not handed to the object-caustics pass even if its material would cast
  // (the host decided the plugin would refuse it, or its caster budget is spent).
  bool castsCaustics = true;
};

struct Model {
  std::vector<Mesh> meshes;
  std::vector<Material> materials;
  std::vector<Instance> instances;
};

// Appends src to dst with every src instance pre-multiplied by `transform`; mesh and material
// indices are re-based so dst stays self-consistent.
void appendModel(Model& dst, const Model& src, const glm::mat4& transform = glm::mat4(1.0f));

// Returns the index of the new mesh; its material must already be an index into the model.
std::uint32_t addMeshInstance(Model& model, Mesh mesh, const glm::mat4& transform,
                              const std::string& instanceName);

std::size_t triangleCount(const Model& model);
std::size_t vertexCount(const Model& model);

}  // namespace ocean_scene
