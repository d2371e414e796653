#include "gltf_indices.h"

#include <cmath>
#include <cstdint>

#include <nlohmann/json.hpp>

#include "gltf_text.h"

namespace ocean_scene::gltf {

namespace {

using Json = nlohmann::json;

std::string at(const std::string& path, std::size_t i) {
  return path + "[" + std::to_string(i) + "]";
}

struct IndexCheck {
  std::string error;

  // object[key], when present, is an index into the root's `array`.
  bool one(const Json& object, const char* key, const std::string& path, const char* array) {
    if (!object.is_object()) return true;
    const auto it = object.find(key);
    if (it == object.end()) return true;
    return value(*it, path.empty() ? key : path + "." + key, array);
  }

  bool value(const Json& v, const std::string& where, const char* array) {
    const std::string written = notANaturalNumber(v);
    if (written.empty()) return true;
    error = where + " is " + written +
            "; an index must be an integer >= 0 (the position of an entry of \"" + array +
            "\"), written without sign, fraction or exponent: leave " + where +
            " out to refer to none";
    return false;
  }

  // object[key], when an array, holds indices into `array`.
  bool each(const Json& object, const char* key, const std::string& path, const char* array) {
    if (!object.is_object()) return true;
    const auto it = object.find(key);
    if (it == object.end() || !it->is_array()) return true;
    for (std::size_t i = 0; i < it->size(); ++i) {
      if (!value((*it)[i], at(path + "." + key, i), array)) return false;
    }
    return true;
  }

  // Each member of object[key] (a primitive's attributes) is an index into `array`.
  bool members(const Json& object, const char* key, const std::string& path, const char* array) {
    if (!object.is_object()) return true;
    const auto it = object.find(key);
    if (it == object.end() || !it->is_object()) return true;
    for (auto m = it->begin(); m != it->end(); ++m) {
      if (!value(*m, path + "." + key + "." + excerpt(m.key()), array)) return false;
    }
    return true;
  }

  // The texture infos anywhere in a material ("baseColorTexture", an extension's
  // "transmissionTexture"): their index and texCoord.
  bool textures(const Json& object, const std::string& path) {
    for (auto m = object.begin(); m != object.end(); ++m) {
      const std::string& key = m.key();
      if (key == "extras" || !m->is_object()) continue;
      const std::string where = path + "." + excerpt(key);
      const bool info = key.size() > 7 && key.compare(key.size() - 7, 7, "Texture") == 0;
      if (info && !(one(*m, "index", where, "textures") &&
                    one(*m, "texCoord", where, "the primitive's TEXCOORD_n attributes"))) {
        return false;
      }
      if (!textures(*m, where)) return false;
    }
    return true;
  }

  const Json* extension(const Json& object, const char* name) {
    const auto extensions = object.find("extensions");
    if (extensions == object.end() || !extensions->is_object()) return nullptr;
    const auto it = extensions->find(name);
    return it == extensions->end() ? nullptr : &*it;
  }

  // Calls check(item, "array[i]") for each object of root[array].
  template <class Check>
  bool items(const Json& root, const char* array, Check check) {
    const auto it = root.find(array);
    if (it == root.end() || !it->is_array()) return true;
    for (std::size_t i = 0; i < it->size(); ++i) {
      if ((*it)[i].is_object() && !check((*it)[i], at(array, i))) return false;
    }
    return true;
  }

  bool primitive(const Json& p, const std::string& path) {
    if (!(one(p, "indices", path, "accessors") && one(p, "material", path, "materials") &&
          members(p, "attributes", path, "accessors"))) {
      return false;
    }
    if (const auto targets = p.find("targets"); targets != p.end() && targets->is_array()) {
      for (std::size_t t = 0; t < targets->size(); ++t) {
        const Json& target = (*targets)[t];
        if (!target.is_object()) continue;
        for (auto m = target.begin(); m != target.end(); ++m) {
          if (!value(*m, at(path + ".targets", t) + "." + excerpt(m.key()), "accessors")) {
            return false;
          }
        }
      }
    }
    const Json* draco = extension(p, "KHR_draco_mesh_compression");
    const std::string dracoPath = path + ".extensions.KHR_draco_mesh_compression";
    return draco == nullptr ||
           (one(*draco, "bufferView", dracoPath, "bufferViews") &&
            members(*draco, "attributes", dracoPath, "the Draco data's attributes"));
  }

  bool all(const Json& root) {
    const auto node = [&](const Json& n, const std::string& path) {
      const Json* instancing = extension(n, "EXT_mesh_gpu_instancing");
      return one(n, "mesh", path, "meshes") && one(n, "camera", path, "cameras") &&
             one(n, "skin", path, "skins") && each(n, "children", path, "nodes") &&
             (instancing == nullptr ||
              members(*instancing, "attributes", path + ".extensions.EXT_mesh_gpu_instancing",
                      "accessors"));
    };
    const auto mesh = [&](const Json& m, const std::string& path) {
      const auto primitives = m.find("primitives");
      if (primitives == m.end() || !primitives->is_array()) return true;
      for (std::size_t i = 0; i < primitives->size(); ++i) {
        const Json& p = (*primitives)[i];
        if (p.is_object() && !primitive(p, at(path + ".primitives", i))) return false;
      }
      return true;
    };
    const auto accessor = [&](const Json& a, const std::string& path) {
      const auto sparse = a.find("sparse");
      const bool sparseOk = sparse == a.end() || !sparse->is_object() ||
                            (one(sparse->value("indices", Json::object()), "bufferView",
                                 path + ".sparse.indices", "bufferViews") &&
                             one(sparse->value("values", Json::object()), "bufferView",
                                 path + ".sparse.values", "bufferViews"));
      return one(a, "bufferView", path, "bufferViews") && sparseOk;
    };
    const auto view = [&](const Json& v, const std::string& path) {
      const Json* meshopt = extension(v, "EXT_meshopt_compression");
      return one(v, "buffer", path, "buffers") &&
             (meshopt == nullptr ||
              one(*meshopt, "buffer", path + ".extensions.EXT_meshopt_compression", "buffers"));
    };
    const auto skin = [&](const Json& s, const std::string& path) {
      return one(s, "inverseBindMatrices", path, "accessors") &&
             one(s, "skeleton", path, "nodes") && each(s, "joints", path, "nodes");
    };
    const auto animation = [&](const Json& a, const std::string& path) {
      const auto channel = [&](const Json& c, const std::string& where) {
        return one(c, "sampler", where, "the animation's samplers") &&
               one(c.value("target", Json::object()), "node", where + ".target", "nodes");
      };
      const auto sampler = [&](const Json& s, const std::string& where) {
        return one(s, "input", where, "accessors") && one(s, "output", where, "accessors");
      };
      return items(
                 a, "channels",
                 [&](const Json& c, const std::string& p) { return channel(c, path + "." + p); }) &&
             items(a, "samplers",
                   [&](const Json& s, const std::string& p) { return sampler(s, path + "." + p); });
    };
    return one(root, "scene", "", "scenes") &&
           items(
               root, "scenes",
               [&](const Json& s, const std::string& p) { return each(s, "nodes", p, "nodes"); }) &&
           items(root, "nodes", node) && items(root, "meshes", mesh) &&
           items(root, "accessors", accessor) && items(root, "bufferViews", view) &&
           items(root, "images",
                 [&](const Json& i, const std::string& p) {
                   return one(i, "bufferView", p, "bufferViews");
                 }) &&
           items(root, "textures",
                 [&](const Json& t, const std::string& p) {
                   return one(t, "source", p, "images") && one(t, "sampler", p, "samplers");
                 }) &&
           items(root, "materials",
                 [&](const Json& m, const std::string& p) { return textures(m, p); }) &&
           items(root, "skins", skin) && items(root, "animations", animation);
  }
};

}  // namespace

std::string notANaturalNumber(const Json& value) {
  if (value.is_number_unsigned()) return "";
  // nlohmann reads every integer written with a '-' as signed, so a signed 0 was written -0.
  if (value.is_number_integer()) {
    const std::int64_t v = value.get<std::int64_t>();
    return v == 0 ? "-0" : std::to_string(v);
  }
  if (value.is_number_float()) return value.dump();  // "24.0", "-0.0", "1e+20"
  if (value.is_string()) return "a string (\"" + excerpt(value.get<std::string>()) + "\")";
  if (value.is_boolean()) return value.get<bool>() ? "true" : "false";
  if (value.is_null()) return "null";
  return value.is_array() ? "an array" : "an object";
}

std::string naturalNumberRule(const Json& value) {
  std::string rule = "it must be a non-negative integer";
  if (value.is_number_float() && value.get<double>() >= 0.0 &&
      value.get<double>() == std::floor(value.get<double>()) && value.get<double>() < 1e15) {
    const std::string whole = std::to_string(static_cast<std::uint64_t>(value.get<double>()));
    rule += " written as one (" + whole + ", not " + value.dump() + " or an exponent)";
  } else if (value.is_number_integer() && value.get<std::int64_t>() == 0) {
    rule += ", written without a sign (0, not -0)";
  }
  return rule;
}

bool indicesValid(const Json& root, std::string& error) {
  IndexCheck check;
  if (check.all(root)) return true;
  error = check.error;
  return false;
}

}  // namespace ocean_scene::gltf
