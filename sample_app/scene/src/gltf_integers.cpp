#include "gltf_integers.h"

#include <climits>
#include <cstdint>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "gltf_text.h"

namespace ocean_scene::gltf {

namespace {

using Json = nlohmann::json;

// The extensions whose integers the loader reads (through tinygltf's int Values).
bool readExtension(std::string_view name) {
  return name == "KHR_draco_mesh_compression" || name == "EXT_meshopt_compression" ||
         name == "EXT_mesh_gpu_instancing" || name.substr(0, 14) == "KHR_materials_";
}

// Fields tinygltf parses as size_t: top-level array name, member.
bool wideField(std::string_view array, std::string_view key) {
  if (array == "accessors") return key == "byteOffset" || key == "count" || key == "componentType";
  if (array == "bufferViews") {
    return key == "byteOffset" || key == "byteLength" || key == "byteStride";
  }
  return array == "buffers" && key == "byteLength";
}

// before + text + after, appended in order (GCC 12 warns, wrongly, of an overlapping copy when
// operator+ prepends a literal to a temporary string).
std::string joined(const char* before, const std::string& text, const char* after = "") {
  std::string out(before);
  out.append(text).append(after);
  return out;
}

struct Walk {
  std::vector<std::string> path;  // "accessors", "[0]", ".sparse", ...
  std::string error;

  std::string where() const {
    std::string text;
    for (const std::string& part : path) text += part;
    return text;
  }

  bool visit(const Json& value, bool wide) {
    if (value.is_number_unsigned()) {
      const std::uint64_t v = value.get<std::uint64_t>();
      if (wide || v <= std::uint64_t(INT_MAX)) return true;
      error = where() + " is " + std::to_string(v) +
              ", beyond the 32-bit range this loader reads (at most 2147483647)";
      return false;
    }
    if (value.is_number_integer()) {
      const std::int64_t v = value.get<std::int64_t>();
      if (v >= INT_MIN && v <= INT_MAX) return true;
      error = where() + " is " + std::to_string(v) +
              ", beyond the 32-bit range this loader reads (at least -2147483648)";
      return false;
    }
    if (value.is_array()) {
      for (std::size_t i = 0; i < value.size(); ++i) {
        path.push_back(joined("[", std::to_string(i), "]"));
        const bool ok = visit(value[i], false);
        path.pop_back();
        if (!ok) return false;
      }
      return true;
    }
    if (!value.is_object()) return true;
    // The member of a top-level array's item: root[array][i][key].
    const bool item = path.size() == 2;
    for (auto it = value.begin(); it != value.end(); ++it) {
      const std::string& key = it.key();
      if (key == "extras") continue;
      const bool extensions = key == "extensions";
      path.push_back(joined(path.empty() ? "" : ".", excerpt(key)));
      bool ok = true;
      if (extensions && it->is_object()) {
        for (auto e = it->begin(); e != it->end() && ok; ++e) {
          if (!readExtension(e.key())) continue;
          path.push_back(joined(".", excerpt(e.key())));
          ok = visit(*e, false);
          path.pop_back();
        }
      } else {
        ok = visit(*it, item && wideField(path[0], key));
      }
      path.pop_back();
      if (!ok) return false;
    }
    return true;
  }
};

}  // namespace

bool integersFit(const Json& root, std::string& error) {
  Walk walk;
  if (walk.visit(root, false)) return true;
  error = walk.error;
  return false;
}

}  // namespace ocean_scene::gltf
