#include "gltf_instancing.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include "gltf_accessor.h"

namespace ocean_scene::gltf {

bool readGpuInstances(const tinygltf::Model& model, const tinygltf::Node& node,
                      std::vector<glm::dmat4>& out, std::string& error) {
  out.clear();
  const auto extension = node.extensions.find("EXT_mesh_gpu_instancing");
  if (extension == node.extensions.end()) return true;
  const tinygltf::Value& attributes = extension->second.Get("attributes");
  if (!attributes.IsObject()) {
    error = "EXT_mesh_gpu_instancing has no attributes object";
    return false;
  }
  // Spec: TRANSLATION/SCALE are VEC3 float, ROTATION VEC4 float or normalised byte/short.
  const bool quantized = std::find(model.extensionsUsed.begin(), model.extensionsUsed.end(),
                                   "KHR_mesh_quantization") != model.extensionsUsed.end();
  std::vector<float> columns[3];
  const char* names[3] = {"TRANSLATION", "ROTATION", "SCALE"};
  const int types[3] = {TINYGLTF_TYPE_VEC3, TINYGLTF_TYPE_VEC4, TINYGLTF_TYPE_VEC3};
  std::size_t count = 0;
  bool any = false;
  for (int a = 0; a < 3; ++a) {
    const tinygltf::Value& index = attributes.Get(names[a]);
    if (!index.IsInt() && !index.IsNumber()) continue;
    const int accessor = index.GetNumberAsInt();
    if (!readFloats(model, accessor, std::string("instance ") + names[a], types[a],
                    quantized || a == 1, columns[a], error)) {
      return false;
    }
    const std::size_t n = columns[a].size() / (a == 1 ? 4u : 3u);
    if (any && n != count) {
      error = "EXT_mesh_gpu_instancing attributes have different counts";
      return false;
    }
    count = n;
    any = true;
  }
  if (!any) {
    error = "EXT_mesh_gpu_instancing names no TRANSLATION, ROTATION or SCALE accessor";
    return false;
  }
  if (count > kMaxGpuInstances) {
    error = "EXT_mesh_gpu_instancing asks for " + std::to_string(count) +
            " instances; the sample draws at most " + std::to_string(kMaxGpuInstances);
    return false;
  }
  out.reserve(count);
  for (std::size_t i = 0; i < count; ++i) {
    glm::dvec3 t(0.0), s(1.0);
    glm::dquat r(1.0, 0.0, 0.0, 0.0);
    if (!columns[0].empty())
      t = glm::dvec3(columns[0][3 * i], columns[0][3 * i + 1], columns[0][3 * i + 2]);
    if (!columns[2].empty())
      s = glm::dvec3(columns[2][3 * i], columns[2][3 * i + 1], columns[2][3 * i + 2]);
    if (!columns[1].empty()) {
      const float* q = &columns[1][4 * i];
      r = glm::dquat(q[3], q[0], q[1], q[2]);  // glTF order x, y, z, w
      const double length = glm::length(r);
      if (!(length > 1e-6) || !std::isfinite(length)) {
        error = "EXT_mesh_gpu_instancing rotation " + std::to_string(i) + " is not a rotation";
        return false;
      }
      r /= length;
    }
    out.push_back(glm::translate(glm::dmat4(1.0), t) * glm::mat4_cast(r) *
                  glm::scale(glm::dmat4(1.0), s));
  }
  return true;
}

}  // namespace ocean_scene::gltf
