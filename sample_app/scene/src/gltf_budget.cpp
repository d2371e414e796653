#include "gltf_budget.h"

#include <cstdint>
#include <limits>
#include <unordered_set>
#include <vector>

#include <nlohmann/json.hpp>

#include "gltf_text.h"
#include "scene/model.h"

namespace ocean_scene::gltf {

namespace {

using Json = nlohmann::json;
using u64 = std::uint64_t;

// Sums and products that stop at the largest u64 instead of wrapping: a file may claim 2^63.
u64 add(u64 a, u64 b) {
  return a > std::numeric_limits<u64>::max() - b ? std::numeric_limits<u64>::max() : a + b;
}
u64 mul(u64 a, u64 b) {
  return b != 0 && a > std::numeric_limits<u64>::max() / b ? std::numeric_limits<u64>::max()
                                                           : a * b;
}

const Json* array(const Json& object, const char* key) {
  const auto it = object.find(key);
  return it != object.end() && it->is_array() ? &*it : nullptr;
}

// object[key] as a count (a non-negative integer, possibly written as 3.0); 0 otherwise.
u64 number(const Json& object, const char* key) {
  if (!object.is_object()) return 0;
  const auto it = object.find(key);
  if (it == object.end()) return 0;
  if (it->is_number_unsigned()) return it->get<u64>();
  if (it->is_number_float()) {
    const double v = it->get<double>();
    return v >= 0.0 && v < 18446744073709551616.0 ? u64(v) : 0;
  }
  return 0;
}

// object[key] as an index into `items`; -1 when absent, not an index or out of range.
long long indexInto(const Json& object, const char* key, const Json* items) {
  if (items == nullptr || !object.is_object()) return -1;
  const auto it = object.find(key);
  if (it == object.end() || !it->is_number_unsigned()) return -1;
  const u64 i = it->get<u64>();
  return i < items->size() ? static_cast<long long>(i) : -1;
}

struct MeshWork {
  u64 primitives = 0, triangles = 0;
};

struct Totals {
  u64 nodes = 0, instances = 0, triangles = 0, bytes = 0;
};

// One primitive's triangles and the bytes its Mesh takes (positions and normals, 24 bytes a
// vertex; the triangle list, 12 bytes a triangle).
void primitiveWork(const Json& primitive, const Json* accessors, u64& triangles, u64& bytes) {
  const auto attributes = primitive.find("attributes");
  const long long position =
      attributes == primitive.end() ? -1 : indexInto(*attributes, "POSITION", accessors);
  const u64 vertices = position < 0 ? 0 : number((*accessors)[std::size_t(position)], "count");
  const long long indexAccessor = indexInto(primitive, "indices", accessors);
  const u64 corners =
      indexAccessor < 0 ? vertices : number((*accessors)[std::size_t(indexAccessor)], "count");
  const u64 mode = primitive.contains("mode") ? number(primitive, "mode") : 4;  // glTF's default
  triangles = mode == 4 ? corners / 3 : (mode == 5 || mode == 6) && corners > 2 ? corners - 2 : 0;
  bytes = add(mul(vertices, 24), mul(triangles, 12));
}

// EXT_mesh_gpu_instancing copies of a node: the count of its first attribute accessor.
u64 copiesOf(const Json& node, const Json* accessors) {
  const auto extensions = node.find("extensions");
  if (extensions == node.end() || !extensions->is_object()) return 1;
  const auto instancing = extensions->find("EXT_mesh_gpu_instancing");
  if (instancing == extensions->end() || !instancing->is_object()) return 1;
  const auto attributes = instancing->find("attributes");
  if (attributes == instancing->end() || !attributes->is_object()) return 1;
  for (const char* name : {"TRANSLATION", "ROTATION", "SCALE"}) {
    const long long a = indexInto(*attributes, name, accessors);
    if (a >= 0) return number((*accessors)[std::size_t(a)], "count");
  }
  return 1;
}

// The nodes flattenNodes starts from: the default scene's, or every node nobody's child.
std::vector<std::size_t> roots(const Json& root, const Json* nodes) {
  std::vector<std::size_t> out;
  if (nodes == nullptr) return out;
  const Json* scenes = array(root, "scenes");
  if (scenes != nullptr && !scenes->empty()) {
    const long long s = root.contains("scene") ? indexInto(root, "scene", scenes) : 0;
    if (s < 0) return out;
    const Json* sceneNodes = array((*scenes)[std::size_t(s)], "nodes");
    if (sceneNodes == nullptr) return out;
    for (const Json& n : *sceneNodes) {
      if (n.is_number_unsigned() && n.get<u64>() < nodes->size()) out.push_back(n.get<u64>());
    }
    return out;
  }
  std::vector<bool> isChild(nodes->size(), false);
  for (const Json& node : *nodes) {
    const Json* children = node.is_object() ? array(node, "children") : nullptr;
    if (children == nullptr) continue;
    for (const Json& c : *children) {
      if (c.is_number_unsigned() && c.get<u64>() < nodes->size()) isChild[c.get<u64>()] = true;
    }
  }
  for (std::size_t i = 0; i < nodes->size(); ++i) {
    if (!isChild[i]) out.push_back(i);
  }
  return out;
}

Totals count(const Json& root) {
  Totals t;
  const Json* accessors = array(root, "accessors");
  const Json* meshes = array(root, "meshes");
  const Json* nodes = array(root, "nodes");
  t.nodes = nodes == nullptr ? 0 : nodes->size();
  // Buffers and meshopt views are held whole once loaded.
  if (const Json* buffers = array(root, "buffers")) {
    for (const Json& b : *buffers) t.bytes = add(t.bytes, number(b, "byteLength"));
  }
  if (const Json* views = array(root, "bufferViews")) {
    for (const Json& v : *views) {
      const auto extensions = v.is_object() ? v.find("extensions") : v.end();
      if (extensions == v.end() || !extensions->is_object()) continue;
      const auto m = extensions->find("EXT_meshopt_compression");
      if (m != extensions->end()) {
        t.bytes = add(t.bytes, mul(number(*m, "count"), number(*m, "byteStride")));
      }
    }
  }
  // Every primitive of every mesh becomes a Mesh, drawn or not.
  std::vector<MeshWork> work(meshes == nullptr ? 0 : meshes->size());
  for (std::size_t m = 0; m < work.size(); ++m) {
    const Json* primitives = array((*meshes)[m], "primitives");
    if (primitives == nullptr || accessors == nullptr) continue;
    for (const Json& primitive : *primitives) {
      if (!primitive.is_object()) continue;
      u64 triangles = 0, bytes = 0;
      primitiveWork(primitive, accessors, triangles, bytes);
      work[m].primitives = add(work[m].primitives, 1);
      work[m].triangles = add(work[m].triangles, triangles);
      t.bytes = add(t.bytes, bytes);
    }
  }
  // Instances and triangles after instancing, over the node tree flattenNodes will walk; a
  // node reached twice is counted once (flattenNodes refuses the file).
  std::vector<std::size_t> stack = roots(root, nodes);
  std::vector<bool> visited(nodes == nullptr ? 0 : nodes->size(), false);
  while (!stack.empty()) {
    const std::size_t n = stack.back();
    stack.pop_back();
    if (visited[n]) continue;
    visited[n] = true;
    const Json& node = (*nodes)[n];
    if (!node.is_object()) continue;
    const long long mesh = indexInto(node, "mesh", meshes);
    if (mesh >= 0) {
      const u64 copies = copiesOf(node, accessors);
      t.instances = add(t.instances, mul(copies, work[std::size_t(mesh)].primitives));
      t.triangles = add(t.triangles, mul(copies, work[std::size_t(mesh)].triangles));
    }
    if (const Json* children = array(node, "children")) {
      for (const Json& c : *children) {
        if (c.is_number_unsigned() && c.get<u64>() < nodes->size()) stack.push_back(c.get<u64>());
      }
    }
  }
  t.bytes = add(t.bytes, mul(t.instances, sizeof(Instance)));
  return t;
}

// One pass over the JSON text that builds nothing: counts its values (stopping at the limit,
// so a file of 50 M zeros costs the scan of 4 M), the entries of the root's "nodes" array,
// and refuses the first duplicate key of an object (nlohmann keeps the last, tinygltf reads
// some keys from the first: 70 "nodes" arrays were counted as 70 x 1000 nodes). Depths: the
// root object's members are at 1, the nodes array's entries at 2.
struct JsonCounter : nlohmann::json_sax<Json> {
  struct Open {
    bool array = false;
    u64 entries = 0;  // an array's entries so far
    std::string key;  // an object's latest key
    // An object's keys so far: searched in turn while few (most glTF objects have a handful),
    // hashed once there are many (an "extras" map of a million keys).
    std::vector<std::string> few;
    std::unordered_set<std::string> many;

    // False when the object already has `name`.
    bool add(const std::string& name) {
      if (many.empty() && few.size() < 16) {
        for (const std::string& k : few) {
          if (k == name) return false;
        }
        few.push_back(name);
        return true;
      }
      if (many.empty()) many.insert(few.begin(), few.end());
      return many.insert(name).second;
    }
  };
  explicit JsonCounter(u64 valueLimit) : limit(valueLimit) {}

  u64 limit, values = 0, nodes = 0;
  bool nextIsNodes = false, inNodes = false, overLimit = false;
  std::vector<Open> open;
  std::string duplicate;  // the message for the first duplicate key

  // The JSON path of the innermost `frames` open values' entry ("meshes[0].primitives[1]";
  // "" = the root).
  std::string path(std::size_t frames) const {
    std::string text;
    for (std::size_t f = 0; f < frames; ++f) {
      const Open& o = open[f];
      // Appended piece by piece: GCC 12 warns, wrongly, of an overlapping copy otherwise.
      if (o.array) {
        text.append("[").append(std::to_string(o.entries == 0 ? 0 : o.entries - 1)).append("]");
      } else {
        text.append(text.empty() ? "" : ".").append(excerpt(o.key));
      }
    }
    return text;
  }
  bool element() {
    if (inNodes && open.size() == 2) ++nodes;
    nextIsNodes = false;
    if (!open.empty() && open.back().array) ++open.back().entries;
    if (++values > limit) {
      overLimit = true;
      return false;
    }
    return true;
  }
  bool null() override { return element(); }
  bool boolean(bool) override { return element(); }
  bool number_integer(number_integer_t) override { return element(); }
  bool number_unsigned(number_unsigned_t) override { return element(); }
  bool number_float(number_float_t, const string_t&) override { return element(); }
  bool string(string_t&) override { return element(); }
  bool binary(binary_t&) override { return element(); }
  bool start_object(std::size_t) override {
    if (!element()) return false;
    open.emplace_back();
    return true;
  }
  bool key(string_t& key) override {
    Open& object = open.back();
    if (!object.add(key)) {
      const std::string where = path(open.size() - 1);
      duplicate = "duplicate key \"" + excerpt(key) + "\" in " +
                  (where.empty() ? "the root object" : where) +
                  "; JSON objects in glTF must have unique keys (which one counts differs from "
                  "reader to reader): keep one";
      return false;
    }
    object.key = key;
    nextIsNodes = open.size() == 1 && key == "nodes";
    if (++values > limit) {
      overLimit = true;
      return false;
    }
    return true;
  }
  bool end_object() override {
    open.pop_back();
    return true;
  }
  bool start_array(std::size_t) override {
    const bool nodesArray = nextIsNodes;
    if (!element()) return false;
    open.emplace_back();
    open.back().array = true;
    if (open.size() == 2 && nodesArray) inNodes = true;
    return true;
  }
  bool end_array() override {
    if (open.size() == 2) inNodes = false;
    open.pop_back();
    return true;
  }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override {
    return false;
  }
};

}  // namespace

std::string refusal(const std::string& over, const std::string& keys, const GltfLimits& limits) {
  std::string text =
      "the model exceeds the work budget: " + over + "; refused before it is expanded";
  if (!limits.raiseOption.empty()) text += " (raise with " + limits.raiseOption + " " + keys + ")";
  return text;
}

bool jsonWithinBudget(std::string_view text, const GltfLimits& limits, std::string& error) {
  JsonCounter counter(limits.jsonValues);
  const bool parsed = Json::sax_parse(text.begin(), text.end(), &counter);
  if (!counter.duplicate.empty()) {
    error = counter.duplicate;
    return false;
  }
  if (counter.overLimit) {
    error = refusal("more than " + std::to_string(limits.jsonValues) + " JSON values (limit " +
                        std::to_string(limits.jsonValues) + ")",
                    "json-values=N", limits);
    return false;
  }
  if (!parsed || counter.nodes <= limits.nodes) return true;
  error =
      refusal(std::to_string(counter.nodes) + " nodes (limit " + std::to_string(limits.nodes) + ")",
              "nodes=N", limits);
  return false;
}

bool withinBudget(const Json& root, const GltfLimits& limits, std::string& error) {
  const Totals t = count(root);
  struct Entry {
    u64 count, limit;
    const char *what, *key;
  };
  const Entry entries[] = {
      {t.nodes, limits.nodes, "nodes", "nodes"},
      {t.instances, limits.instances, "instances after instancing", "instances"},
      {t.triangles, limits.triangles, "triangles after instancing", "triangles"},
      {t.bytes, limits.bytes, "bytes once expanded (buffers, meshes, instances)", "bytes"}};
  std::string over, keys;
  for (const Entry& e : entries) {
    if (e.count <= e.limit) continue;
    // Appended piece by piece: GCC 12 warns, wrongly, of an overlapping copy in the one-line
    // concatenation.
    if (!over.empty()) over += ", ";
    over.append(std::to_string(e.count)).append(" ").append(e.what).append(" (limit ");
    over.append(std::to_string(e.limit)).append(")");
    if (!keys.empty()) keys += ",";
    keys.append(e.key).append("=N");
  }
  if (over.empty()) return true;
  error = refusal(over, keys, limits);
  return false;
}

}  // namespace ocean_scene::gltf
