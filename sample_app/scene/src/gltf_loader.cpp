#include "scene/gltf_loader.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <exception>
#include <limits>
#include <string_view>
#include <vector>

#include <tiny_gltf.h>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "gltf_file.h"
#include "gltf_glb.h"
#include "gltf_instancing.h"
#include "gltf_material.h"
#include "gltf_meshopt.h"
#include "gltf_preflight.h"
#include "gltf_primitive.h"
#include "gltf_stderr.h"
#include "gltf_text.h"
#include "gltf_texture_colour.h"

namespace ocean_scene {

namespace {

// Models and their buffers above this are refused before they are read (tinygltf takes a
// 32-bit length; a sample scene's caster is a few MB).
constexpr std::uint64_t kMaxFileBytes = 1ull << 30;

std::string directoryOf(const std::string& path) {
  const auto slash = path.find_last_of("/\\");
  return slash == std::string::npos ? std::string(".") : path.substr(0, slash);
}

// tinygltf's file access, limited to the buffer files the preflight resolved inside the
// model's folder: nothing else is found (images, the working directory), nothing is expanded
// (tinygltf's default runs wordexp on the path) and nothing is written.
struct GuardedFiles {
  const gltf::Preflight* preflight = nullptr;
};

bool guardedExists(const std::string& path, void* user) {
  return static_cast<GuardedFiles*>(user)->preflight->bufferFiles.count(path) > 0;
}

std::string guardedExpand(const std::string& path, void*) {
  return path;
}

bool guardedRead(std::vector<unsigned char>* out, std::string* err, const std::string& path,
                 void* user) {
  const auto& files = static_cast<GuardedFiles*>(user)->preflight->bufferFiles;
  const auto it = files.find(path);
  std::string problem = "not a buffer file of this model";
  if (it != files.end() && gltf::readRegularFile(it->second, kMaxFileBytes, *out, problem)) {
    return true;
  }
  if (err != nullptr) *err = problem;
  return false;
}

bool guardedWrite(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
  if (err != nullptr) *err = "the loader never writes";
  return false;
}

// Textures are ignored by this loader; skipping decode also keeps image parsers off the path.
bool skipImage(tinygltf::Image*, const int, std::string*, std::string*, int, int,
               const unsigned char*, int, void*) {
  return true;
}

// tinygltf's lines, each bounded (its messages quote names and URIs whole), joined by "; ".
// `skipImages` drops the warnings about the image files this loader keeps from it (it reads a
// base colour's image itself and no other).
std::string tinygltfLines(const std::string& text, bool skipImages) {
  std::string kept;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    const std::string_view line(text.data() + start, end - start);
    start = end + 1;
    const bool image = line.rfind("Failed to load external 'uri' for image[", 0) == 0 ||
                       line.rfind("File not found : ", 0) == 0;
    if (line.empty() || (skipImages && image)) continue;
    kept += (kept.empty() ? "" : "; ") + gltf::excerpt(line);
  }
  return kept;
}

// The file's JSON and buffers in tinygltf's model; `preflight` says what was checked and where
// the base-colour images are.
bool parse(const std::string& path, const std::vector<unsigned char>& bytes,
           const GltfLimits& limits, tinygltf::Model& model, gltf::Preflight& preflight,
           std::string& error, std::string& warnings) {
  const bool binary = gltf::isGlb(bytes);
  const std::string_view text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  if (!binary && !gltf::jsonIsUtf8(text, error)) return false;
  if (!binary && !(bytes[0] == '{' || bytes[0] == ' ' || bytes[0] == '\n' || bytes[0] == '\t' ||
                   bytes[0] == '\r' || bytes[0] == 0xEF /* UTF-8 BOM */)) {
    error = "not a glTF file (no 'glTF' magic and no JSON object)";
    return false;
  }
  const std::string baseDir = directoryOf(path);
  if (!gltf::preflight(bytes, baseDir, limits, preflight, error)) return false;
  if (!preflight.imageUris.empty()) {
    warnings += std::to_string(preflight.imageUris.size()) +
                " image file(s) not read: only a material's base-colour image is used; ";
  }
  // Meshopt fallback buffers got placeholders; tinygltf parses the rewritten JSON.
  const std::vector<unsigned char> rewritten = preflight.rewrittenJson.empty()
                                                   ? std::vector<unsigned char>()
                                                   : gltf::withJson(bytes, preflight.rewrittenJson);
  const std::vector<unsigned char>& input = rewritten.empty() ? bytes : rewritten;
  if (input.size() > 0xffffffffu) {  // tinygltf takes an unsigned int length
    error = "the JSON rewritten for tinygltf is larger than 4 GiB";
    return false;
  }
  GuardedFiles guarded{&preflight};
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(&skipImage, nullptr);
  loader.SetFsCallbacks(
      tinygltf::FsCallbacks{&guardedExists, &guardedExpand, &guardedRead, &guardedWrite, &guarded});
  std::string err, warn;
  const auto size = static_cast<unsigned int>(input.size());
  const bool ok =
      binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, input.data(), size, baseDir)
             : loader.LoadASCIIFromString(
                   &model, &err, &warn, reinterpret_cast<const char*>(input.data()), size, baseDir);
  if (const std::string kept = tinygltfLines(warn, true); !kept.empty()) {
    warnings += "tinygltf: " + kept + "; ";
  }
  if (!ok) {
    const std::string said = tinygltfLines(err, false);
    error = said.empty() ? "tinygltf could not parse the file" : "tinygltf: " + said;
    return false;
  }
  return gltf::decodeMeshoptViews(model, preflight.meshoptFallbacks, error);
}

bool nodeLocalTransform(const tinygltf::Node& node, glm::dmat4& out, std::string& error) {
  if (node.matrix.size() == 16) {
    out = glm::make_mat4(node.matrix.data());  // glTF and GLM are both column-major
  } else if (!node.matrix.empty()) {
    error = "node '" + gltf::excerpt(node.name) + "' matrix does not have 16 elements";
    return false;
  } else {
    glm::dvec3 t(0.0), s(1.0);
    glm::dquat r(1.0, 0.0, 0.0, 0.0);
    if (node.translation.size() == 3) t = glm::make_vec3(node.translation.data());
    if (node.scale.size() == 3) s = glm::make_vec3(node.scale.data());
    if (node.rotation.size() == 4) {  // glTF order x, y, z, w
      r = glm::dquat(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
    }
    if ((!node.translation.empty() && node.translation.size() != 3) ||
        (!node.scale.empty() && node.scale.size() != 3) ||
        (!node.rotation.empty() && node.rotation.size() != 4)) {
      error =
          "node '" + gltf::excerpt(node.name) + "' has a malformed translation, rotation or scale";
      return false;
    }
    out = glm::translate(glm::dmat4(1.0), t) * glm::mat4_cast(glm::normalize(r)) *
          glm::scale(glm::dmat4(1.0), s);
  }
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) {
      if (!std::isfinite(out[c][r])) {
        error = "node '" + gltf::excerpt(node.name) + "' has a non-finite transform";
        return false;
      }
    }
  }
  return true;
}

std::string nodeLabel(std::size_t index, const tinygltf::Node& node) {
  return "node " + std::to_string(index) +
         (node.name.empty() ? "" : " '" + gltf::excerpt(node.name) + "'");
}

// Scene coordinates beyond this lose centimetres in float and leave the sample's ~100 m scene
// far behind; a transform that puts a mesh there is an error in the file, not a placement.
constexpr double kMaxCoordinate = 1e6;

// Checks the composed transform after the conversion to float the renderer uses: only each
// node's own transform was checked before, so a chain of large ones could overflow unseen.
// Returns "" when it is usable, else why not; `hidden` says the node is merely invisible
// (not invertible: scale 0, a common way to hide a node), which is not an error.
std::string composedProblem(const glm::dmat4& world, const glm::vec3& lo, const glm::vec3& hi,
                            bool& hidden) {
  hidden = false;
  const glm::mat4 f(world);
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) {
      if (!std::isfinite(f[c][r])) return "its composed transform overflows float";
    }
  }
  if (f[0][3] != 0.0f || f[1][3] != 0.0f || f[2][3] != 0.0f || f[3][3] != 1.0f) {
    return "its composed transform is projective (bottom row not 0 0 0 1)";
  }
  // The plugin's own test for a caster (postfx casters: |det| > 1e-30 in double).
  if (!(std::abs(glm::determinant(glm::dmat3(glm::mat3(f)))) > 1e-30)) {
    hidden = true;
    return "its transform is not invertible (scale 0 hides it)";
  }
  for (int corner = 0; corner < 8; ++corner) {
    const glm::dvec3 p((corner & 1) ? hi.x : lo.x, (corner & 2) ? hi.y : lo.y,
                       (corner & 4) ? hi.z : lo.z);
    const glm::dvec4 q = glm::dmat4(f) * glm::dvec4(p, 1.0);
    if (!(glm::all(glm::lessThanEqual(glm::abs(glm::dvec3(q)), glm::dvec3(kMaxCoordinate))))) {
      return "its transform puts the mesh beyond " + std::to_string(int(kMaxCoordinate)) +
             " m from the origin";
    }
  }
  return "";
}

// meshMap[m] = our mesh indices of glTF mesh m's primitives.
bool flattenNodes(const tinygltf::Model& model,
                  const std::vector<std::vector<std::uint32_t>>& meshMap, Model& out,
                  std::string& error, std::string& notes) {
  std::vector<int> roots;
  if (!model.scenes.empty()) {
    const int sceneIndex = model.defaultScene >= 0 ? model.defaultScene : 0;
    if (static_cast<std::size_t>(sceneIndex) >= model.scenes.size()) {
      error = "defaultScene " + std::to_string(sceneIndex) + " does not exist";
      return false;
    }
    roots = model.scenes[static_cast<std::size_t>(sceneIndex)].nodes;
  } else {
    // No scene: every node that is nobody's child is a root.
    std::vector<bool> isChild(model.nodes.size(), false);
    for (const tinygltf::Node& node : model.nodes) {
      for (int child : node.children) {
        if (child >= 0 && static_cast<std::size_t>(child) < isChild.size()) {
          isChild[static_cast<std::size_t>(child)] = true;
        }
      }
    }
    for (std::size_t i = 0; i < model.nodes.size(); ++i) {
      if (!isChild[i]) roots.push_back(static_cast<int>(i));
    }
    if (roots.empty() && !model.nodes.empty()) {
      error = "the file has no scene, and each of its " + std::to_string(model.nodes.size()) +
              " node(s) is another node's child, so no node is a root: the children form a "
              "cycle (nodes make trees): break the cycle, or add a scene naming the root nodes";
      return false;
    }
  }
  struct Bounds {
    glm::vec3 lo{0.0f}, hi{0.0f};
  };
  std::vector<Bounds> bounds(out.meshes.size());
  for (std::size_t m = 0; m < out.meshes.size(); ++m) {
    const auto& positions = out.meshes[m].positions;
    if (positions.empty()) continue;
    bounds[m].lo = bounds[m].hi = positions[0];
    for (const glm::vec3& p : positions) {
      bounds[m].lo = glm::min(bounds[m].lo, p);
      bounds[m].hi = glm::max(bounds[m].hi, p);
    }
  }
  struct Pending {
    int node;
    glm::dmat4 parent;
  };
  std::vector<Pending> stack;
  for (auto it = roots.rbegin(); it != roots.rend(); ++it) stack.push_back({*it, glm::dmat4(1.0)});
  // A valid hierarchy is a forest: each node is visited at most once.
  std::vector<bool> visited(model.nodes.size(), false);
  std::size_t hiddenCount = 0;
  while (!stack.empty()) {
    const Pending item = stack.back();
    stack.pop_back();
    if (item.node < 0 || static_cast<std::size_t>(item.node) >= model.nodes.size()) {
      error = "node " + std::to_string(item.node) + " does not exist";
      return false;
    }
    const auto nodeIndex = static_cast<std::size_t>(item.node);
    if (visited[nodeIndex]) {
      error = "node " + std::to_string(item.node) + " is reached twice (cycle or shared child)";
      return false;
    }
    visited[nodeIndex] = true;
    const tinygltf::Node& node = model.nodes[nodeIndex];
    glm::dmat4 local;
    if (!nodeLocalTransform(node, local, error)) return false;
    const glm::dmat4 world = item.parent * local;
    if (node.mesh >= 0) {
      if (static_cast<std::size_t>(node.mesh) >= meshMap.size()) {
        error = nodeLabel(nodeIndex, node) + " refers to missing mesh " + std::to_string(node.mesh);
        return false;
      }
      std::vector<glm::dmat4> copies;
      if (!gltf::readGpuInstances(model, node, copies, error)) {
        error = nodeLabel(nodeIndex, node) + ": " + error;
        return false;
      }
      if (copies.empty()) copies.push_back(glm::dmat4(1.0));
      for (const glm::dmat4& copy : copies) {
        const glm::dmat4 placed = world * copy;
        for (std::uint32_t mesh : meshMap[static_cast<std::size_t>(node.mesh)]) {
          bool hidden = false;
          const std::string problem =
              composedProblem(placed, bounds[mesh].lo, bounds[mesh].hi, hidden);
          if (hidden) {
            // Left out with a note: drawing it would show nothing, and the plugin refuses it.
            if (++hiddenCount <= 4) {
              notes += nodeLabel(nodeIndex, node) + " left out: " + problem + "; ";
            }
            break;
          }
          if (!problem.empty()) {
            error = nodeLabel(nodeIndex, node) + ": " + problem;
            return false;
          }
          out.instances.push_back(Instance{mesh, glm::mat4(placed), gltf::excerpt(node.name)});
        }
      }
    }
    for (auto it = node.children.rbegin(); it != node.children.rend(); ++it) {
      stack.push_back({*it, world});
    }
  }
  if (hiddenCount > 4) {
    notes += std::to_string(hiddenCount - 4) + " more hidden node(s) left out; ";
  }
  if (out.instances.empty()) {
    const std::string scene =
        model.scenes.empty()
            ? std::string("the file (no scene: its root nodes)")
            : "scenes[" + std::to_string(model.defaultScene >= 0 ? model.defaultScene : 0) + "]";
    error = hiddenCount > 0 ? "every node with a mesh is hidden (transform not invertible)"
                            : scene + " has no node with a mesh (it reaches " +
                                  std::to_string(std::count(visited.begin(), visited.end(), true)) +
                                  " of the file's " + std::to_string(model.nodes.size()) +
                                  " node(s)): there is nothing to draw";
    return false;
  }
  return true;
}

// The note on a textured material's textures: what its colour took from them, what it left
// out and why ("shaded from its factors, without baseColorTexture (its image is not PNG or
// JPEG), normalTexture").
std::string textureNote(const tinygltf::Material& source, bool averaged, const std::string& why) {
  const std::string others = gltf::ignoredTextures(source, true);
  if (averaged) {
    return "baseColorTexture averaged into its colour" + (why.empty() ? "" : " (" + why + ")") +
           (others.empty() ? "" : ", without " + others);
  }
  std::string unused = source.pbrMetallicRoughness.baseColorTexture.index >= 0
                           ? "baseColorTexture (" + why + ")"
                           : std::string();
  if (!others.empty()) unused += (unused.empty() ? "" : ", ") + others;
  return "shaded from its factors, without " + unused;
}

bool convert(const tinygltf::Model& model, const gltf::Preflight& preflight,
             const GltfLimits& limits, Model& out, std::string& error, std::string& notes) {
  // Textures: the base colour's is averaged into the colour, from wherever the image is; the
  // rest are named in a note (the first few materials by name, then a count), since the
  // sample shades from factors only.
  constexpr int kNamed = 4;
  int textured = 0;
  gltf::ImageMeans means;
  if (!gltf::baseColourImageMeans(model, preflight, limits, means, error)) return false;
  for (std::size_t i = 0; i < model.materials.size(); ++i) {
    const tinygltf::Material& source = model.materials[i];
    Material material;
    if (!gltf::readMaterial(source, material, error)) return false;
    material.name = gltf::excerpt(material.name);  // printed in the sample's warnings
    glm::vec3 mean(1.0f);
    std::string why;
    const bool averaged = gltf::baseColourTextureMean(model, means, source, mean, why);
    if (averaged) material.baseColor *= mean;
    const bool hasTextures = source.pbrMetallicRoughness.baseColorTexture.index >= 0 ||
                             !gltf::ignoredTextures(source, true).empty();
    if (hasTextures && textured++ < kNamed) {
      notes += "material '" + material.name + "': " + textureNote(source, averaged, why) + "; ";
    }
    out.materials.push_back(std::move(material));
  }
  if (textured > kNamed) {
    notes += std::to_string(textured - kNamed) + " more textured material(s); ";
  }
  // Primitives without a material get the glTF default material, added once at the end.
  std::uint32_t defaultMaterial = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::vector<std::uint32_t>> meshMap(model.meshes.size());
  for (std::size_t m = 0; m < model.meshes.size(); ++m) {
    const tinygltf::Mesh& source = model.meshes[m];
    for (std::size_t p = 0; p < source.primitives.size(); ++p) {
      const tinygltf::Primitive& primitive = source.primitives[p];
      Mesh mesh;
      mesh.name = gltf::excerpt(source.name) +
                  (source.primitives.size() == 1 ? "" : "#" + std::to_string(p));
      if (!gltf::readPrimitive(model, primitive, mesh, error, notes)) {
        error = "mesh " + std::to_string(m) + " '" + gltf::excerpt(source.name) + "' primitive " +
                std::to_string(p) + ": " + error;
        return false;
      }
      if (primitive.material >= 0) {
        if (static_cast<std::size_t>(primitive.material) >= out.materials.size()) {
          error = "mesh " + std::to_string(m) + " '" + gltf::excerpt(source.name) +
                  "' refers to missing material " + std::to_string(primitive.material);
          return false;
        }
        mesh.material = static_cast<std::uint32_t>(primitive.material);
      } else {
        if (defaultMaterial == std::numeric_limits<std::uint32_t>::max()) {
          defaultMaterial = static_cast<std::uint32_t>(out.materials.size());
          Material fallback;
          fallback.name = "gltf_default";
          out.materials.push_back(fallback);
        }
        mesh.material = defaultMaterial;
      }
      meshMap[m].push_back(static_cast<std::uint32_t>(out.meshes.size()));
      out.meshes.push_back(std::move(mesh));
    }
  }
  return flattenNodes(model, meshMap, out, error, notes);
}

}  // namespace

bool loadGlb(const std::string& path, Model& out, std::string& error, std::string* warnings,
             const GltfLimits& limits) {
  out = Model{};
  std::string problem, notes;
  bool ok = false;
  // Whatever a library prints meanwhile (Draco, tinygltf; libpng's are caught closer, in
  // the texture's reason) is named in this file's message instead of reaching stderr.
  gltf::StderrCapture capture;
  try {
    std::vector<unsigned char> bytes;
    tinygltf::Model model;
    gltf::Preflight preflight;
    ok = gltf::readRegularFile(path, kMaxFileBytes, bytes, problem) &&
         parse(path, bytes, limits, model, preflight, problem, notes) &&
         convert(model, preflight, limits, out, problem, notes);
  } catch (const std::exception& e) {
    problem = std::string("unexpected failure: ") + e.what();
    ok = false;
  } catch (...) {
    problem = "unexpected failure";
    ok = false;
  }
  const std::string printed = capture.take();
  if (!printed.empty()) {
    (ok ? notes : problem) += std::string(ok ? "" : " ") + "(library output: " + printed + ")";
  }
  if (!ok) {
    out = Model{};
    error = gltf::excerpt(path) + ": " +
            gltf::excerpt(gltf::safeOneLine(problem), gltf::kMaxMessageChars);
    return false;
  }
  if (warnings != nullptr) {
    *warnings = gltf::excerpt(gltf::safeOneLine(notes), gltf::kMaxNotesChars);
  }
  return true;
}

}  // namespace ocean_scene
