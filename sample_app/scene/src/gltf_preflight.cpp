#include "gltf_preflight.h"

#include <sys/stat.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <string_view>

#include <nlohmann/json.hpp>

#include "gltf_budget.h"
#include "gltf_data_uri.h"
#include "gltf_file.h"
#include "gltf_glb.h"
#include "gltf_indices.h"
#include "gltf_integers.h"
#include "gltf_spec_rules.h"
#include "gltf_text.h"

namespace ocean_scene::gltf {

namespace {

using Json = nlohmann::json;

// The JSON text: a .gltf is all JSON; a .glb holds it in its first chunk.
bool jsonText(const std::vector<unsigned char>& bytes, std::string_view& text, GlbLayout& glb,
              std::string& error) {
  if (!isGlb(bytes)) {
    text = std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    return true;
  }
  if (!readGlbLayout(bytes, glb, error)) return false;
  text = glb.json;
  return true;
}

}  // namespace

bool jsonIsUtf8(std::string_view text, std::string& error) {
  const auto byte = [&](std::size_t i) -> unsigned char {
    return i < text.size() ? static_cast<unsigned char>(text[i]) : 0x20;
  };
  const bool bom = (byte(0) == 0xFF && byte(1) == 0xFE) || (byte(0) == 0xFE && byte(1) == 0xFF);
  // "{" or a space with NULs around it among the first 4 bytes: JSON in 2 or 4 bytes a letter.
  bool nul = false, opens = false;
  for (std::size_t i = 0; i < 4 && i < text.size(); ++i) {
    const unsigned char c = byte(i);
    if (c == 0) {
      nul = true;
    } else {
      opens = c == '{' || c == ' ' || c == '\n' || c == '\r' || c == '\t';
      break;
    }
  }
  for (std::size_t i = 1; !nul && opens && i < 4 && i < text.size(); ++i) nul = byte(i) == 0;
  if (!bom && !(nul && opens)) return true;
  error = "the JSON is UTF-16 or UTF-32 (it starts with bytes " + std::to_string(byte(0)) + " " +
          std::to_string(byte(1)) +
          "); glTF's JSON must be UTF-8: save it as UTF-8 (a UTF-8 byte-order mark is accepted)";
  return false;
}

namespace {

// Nesting depth without recursion; strings (with escapes) are skipped so brackets in names
// do not count.
bool depthWithin(std::string_view text, int limit, std::string& error) {
  int depth = 0;
  bool inString = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (inString) {
      if (c == '\\') {
        ++i;
      } else if (c == '"') {
        inString = false;
      }
      continue;
    }
    if (c == '"') {
      inString = true;
    } else if (c == '[' || c == '{') {
      if (++depth > limit) {
        error = "JSON nests deeper than " + std::to_string(limit) + " levels (at byte " +
                std::to_string(i) + "); refused before parsing";
        return false;
      }
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
  return true;
}

// The feature each refused extension stands for, so the message says what is missing.
std::string describeExtension(const std::string& name) {
  if (name == "KHR_meshopt_compression") {
    return "meshopt buffer compression " + name +
           " is not supported (EXT_meshopt_compression is); export with the EXT extension";
  }
  if (name == "KHR_texture_basisu" || name == "EXT_texture_webp" || name == "EXT_texture_avif") {
    return "extension " + name + " is required, but textures are not used by this loader";
  }
  return "extension " + name + " is required by the file but not supported";
}

// Extensions this loader honours (or, for geometry-only ones, makes no difference to).
bool supportedExtension(const std::string& name) {
  return name == "KHR_materials_ior" || name == "KHR_materials_transmission" ||
         name == "KHR_materials_volume" || name == "KHR_mesh_quantization" ||
         name == "EXT_mesh_gpu_instancing" || name == "KHR_draco_mesh_compression" ||
         name == "EXT_meshopt_compression" || name == "KHR_materials_dispersion";
}

bool checkExtensions(const Json& root, Preflight& out, std::string& error) {
  for (const char* key : {"extensionsUsed", "extensionsRequired"}) {
    const auto it = root.find(key);
    if (it == root.end()) continue;
    if (!it->is_array()) {
      error = std::string(key) + " is not an array";
      return false;
    }
    for (const Json& name : *it) {
      if (!name.is_string()) {
        error = std::string(key) + " holds a non-string";
        return false;
      }
      const std::string extension = name.get<std::string>();
      if (extension == "KHR_mesh_quantization") out.meshQuantization = true;
      if (std::strcmp(key, "extensionsRequired") == 0 && !supportedExtension(extension)) {
        error = describeExtension(extension);
        return false;
      }
    }
  }
  return true;
}

// Sizes, offsets and indices that tinygltf would read as unsigned (so -4 becomes 0 or huge),
// or would refuse with a message naming no accessor when written 24.0 or 2.4e1.
bool nonNegativeInteger(const Json& object, const char* key, const std::string& where,
                        std::string& error) {
  const auto it = object.find(key);
  if (it == object.end()) return true;
  const std::string written = notANaturalNumber(*it);
  if (written.empty()) return true;
  error = where + "." + key + " is " + written + "; " + naturalNumberRule(*it);
  return false;
}

bool checkArrayFields(const Json& root, const char* array, std::initializer_list<const char*> keys,
                      std::string& error) {
  const auto it = root.find(array);
  if (it == root.end()) return true;
  if (!it->is_array()) {
    error = std::string(array) + " is not an array";
    return false;
  }
  for (std::size_t i = 0; i < it->size(); ++i) {
    const Json& item = (*it)[i];
    if (!item.is_object()) {
      error = std::string(array) + "[" + std::to_string(i) + "] is not an object";
      return false;
    }
    const std::string where = std::string(array) + "[" + std::to_string(i) + "]";
    for (const char* key : keys) {
      if (!nonNegativeInteger(item, key, where, error)) return false;
    }
    const auto sparse = item.find("sparse");
    if (sparse != item.end() && sparse->is_object()) {
      if (!nonNegativeInteger(*sparse, "count", where + ".sparse", error)) return false;
      for (const char* part : {"indices", "values"}) {
        const auto p = sparse->find(part);
        if (p == sparse->end() || !p->is_object()) continue;
        const std::string at = where + ".sparse." + part;
        if (!nonNegativeInteger(*p, "bufferView", at, error) ||
            !nonNegativeInteger(*p, "byteOffset", at, error)) {
          return false;
        }
      }
    }
  }
  return true;
}

// The URI string of item `i` of `array`, or false when it has none.
bool uriOf(const Json& item, std::string& uri) {
  const auto it = item.find("uri");
  if (it == item.end() || !it->is_string()) return false;
  uri = it->get<std::string>();
  return true;
}

bool isMeshoptFallback(const Json& buffer);

// A buffer's data: URI, checked as tinygltf will decode it: base64 of one of the two media
// types it reads as data, exactly byteLength bytes.
bool checkBufferDataUri(const std::string& uri, std::uint64_t byteLength, const std::string& where,
                        std::string& error) {
  const std::string what = where + " data: URI (" + std::to_string(uri.size()) + " bytes) ";
  DataUri data;
  std::string reason;
  if (!checkDataUri(uri, data, reason)) {
    error = what + reason;
    return false;
  }
  if (data.mediaType != "application/octet-stream" && data.mediaType != "application/gltf-buffer") {
    error = what + "has media type '" + excerpt(data.mediaType) +
            "'; a buffer's must be application/octet-stream or application/gltf-buffer";
    return false;
  }
  if (data.decodedSize != byteLength) {
    error = what + "decodes to " + std::to_string(data.decodedSize) + " bytes, byteLength says " +
            std::to_string(byteLength);
    return false;
  }
  return true;
}

std::uint64_t byteLengthOf(const Json& buffer) {
  const auto it = buffer.find("byteLength");
  return it != buffer.end() && it->is_number_unsigned() ? it->get<std::uint64_t>() : 0;
}

bool checkBuffers(const Json& root, const std::string& baseDir, const GlbLayout* glb,
                  Preflight& out, std::string& error) {
  const auto buffers = root.find("buffers");
  if (buffers == root.end() || !buffers->is_array()) return true;
  const std::string folder = realFolder(baseDir);
  for (std::size_t i = 0; i < buffers->size(); ++i) {
    const Json& buffer = (*buffers)[i];
    const std::string name = "buffer " + std::to_string(i);
    const std::uint64_t byteLength = byteLengthOf(buffer);
    std::string uri;
    if (!uriOf(buffer, uri)) {
      if (isMeshoptFallback(buffer)) continue;
      // Without a uri the data is the GLB's BIN chunk: there must be one, long enough.
      if (glb == nullptr) {
        error = name +
                " has no uri; in a .gltf every buffer needs one (a .glb's BIN chunk "
                "is the only buffer without)";
        return false;
      }
      if (glb->binHeader == 0) {
        error = name +
                " has no uri, so it is the BIN chunk, but the GLB has none (its JSON "
                "chunk ends at byte " +
                std::to_string(glb->jsonEnd) + ", the GLB's length)";
        return false;
      }
      if (byteLength > glb->binLength) {
        error = name + " byteLength " + std::to_string(byteLength) + " exceeds the BIN chunk's " +
                std::to_string(glb->binLength) + " bytes (chunk at byte " +
                std::to_string(glb->binHeader) + ")";
        return false;
      }
      continue;
    }
    const std::string where = name + " uri '" + excerpt(uri) + "'";
    if (isDataUri(uri)) {
      if (!checkBufferDataUri(uri, byteLength, name, error)) return false;
      continue;
    }
    const std::string decoded = decodeUri(uri);
    std::string resolved, reason;
    if (!resolveInFolder(folder, uri, decoded, resolved, reason)) {
      error = where + " " + reason;
      return false;
    }
    // The file is inside the model's folder, so its size may be said.
    struct stat status {};
    if (::stat(resolved.c_str(), &status) == 0 && std::uint64_t(status.st_size) != byteLength) {
      error = where + " has " + std::to_string(status.st_size) + " bytes, byteLength says " +
              std::to_string(byteLength);
      return false;
    }
    out.bufferFiles[joinLikeTinygltf(baseDir, decoded)] = resolved;
  }
  return true;
}

bool isMeshoptFallback(const Json& buffer) {
  if (!buffer.is_object() || buffer.contains("uri")) return false;
  const auto extensions = buffer.find("extensions");
  if (extensions == buffer.end() || !extensions->is_object()) return false;
  const auto meshopt = extensions->find("EXT_meshopt_compression");
  if (meshopt == extensions->end() || !meshopt->is_object()) return false;
  const auto fallback = meshopt->find("fallback");
  return fallback != meshopt->end() && fallback->is_boolean() && fallback->get<bool>();
}

// Gives each data-less meshopt fallback buffer a 4-byte placeholder tinygltf can load.
// Returns whether the JSON changed.
bool placeholdMeshoptFallbacks(Json& root, Preflight& out) {
  const auto buffers = root.find("buffers");
  if (buffers == root.end() || !buffers->is_array()) return false;
  std::size_t index = 0;
  for (Json& buffer : *buffers) {
    if (isMeshoptFallback(buffer)) {
      buffer["uri"] = "data:application/octet-stream;base64,AAAAAA==";
      buffer["byteLength"] = 4;
      out.meshoptFallbacks.insert(index);
    }
    ++index;
  }
  return !out.meshoptFallbacks.empty();
}

// A Draco primitive's index accessor has no bufferView (the triangles are in the compressed
// data), which tinygltf refuses; the loader takes the triangles from the Draco data, so the
// primitive's "indices" is dropped. Returns whether the JSON changed.
bool dropDracoIndices(Json& root) {
  const auto meshes = root.find("meshes");
  if (meshes == root.end() || !meshes->is_array()) return false;
  bool changed = false;
  for (Json& mesh : *meshes) {
    if (!mesh.is_object()) continue;
    const auto primitives = mesh.find("primitives");
    if (primitives == mesh.end() || !primitives->is_array()) continue;
    for (Json& primitive : *primitives) {
      if (!primitive.is_object() || !primitive.contains("indices")) continue;
      const auto extensions = primitive.find("extensions");
      if (extensions != primitive.end() && extensions->is_object() &&
          extensions->contains("KHR_draco_mesh_compression")) {
        primitive.erase("indices");
        changed = true;
      }
    }
  }
  return changed;
}

// The images a material's base colour uses (materials -> textures -> source): only those are
// read, to average their colour; every other image is never opened.
std::set<std::size_t> baseColourImages(const Json& root) {
  std::set<std::size_t> used;
  const auto materials = root.find("materials");
  const auto textures = root.find("textures");
  if (materials == root.end() || !materials->is_array() || textures == root.end() ||
      !textures->is_array()) {
    return used;
  }
  for (const Json& material : *materials) {
    const Json* index = nullptr;
    if (material.is_object() && material.contains("pbrMetallicRoughness")) {
      const Json& pbr = material["pbrMetallicRoughness"];
      if (pbr.is_object() && pbr.contains("baseColorTexture") &&
          pbr["baseColorTexture"].is_object() && pbr["baseColorTexture"].contains("index")) {
        index = &pbr["baseColorTexture"]["index"];
      }
    }
    if (index == nullptr || !index->is_number_unsigned() ||
        index->get<std::uint64_t>() >= textures->size()) {
      continue;
    }
    const Json& texture = (*textures)[index->get<std::size_t>()];
    if (texture.is_object() && texture.contains("source") &&
        texture["source"].is_number_unsigned()) {
      used.insert(texture["source"].get<std::size_t>());
    }
  }
  return used;
}

bool collectImages(const Json& root, const std::string& baseDir, Preflight& out,
                   std::string& error) {
  const auto images = root.find("images");
  if (images == root.end() || !images->is_array()) return true;
  const std::set<std::size_t> used = baseColourImages(root);
  const std::string folder = used.empty() ? std::string() : realFolder(baseDir);
  for (std::size_t i = 0; i < images->size(); ++i) {
    std::string uri;
    if (!(*images)[i].is_object() || !uriOf((*images)[i], uri)) continue;  // a bufferView's
    const bool baseColour = used.count(i) > 0;
    if (isDataUri(uri)) {
      // tinygltf decodes it (a base-colour image or not), so a broken one is refused with the
      // reason, not tinygltf's echo of the whole URI.
      DataUri data;
      std::string reason;
      if (!checkDataUri(uri, data, reason)) {
        error = "image " + std::to_string(i) + " data: URI (" + std::to_string(uri.size()) +
                " bytes) " + reason;
        return false;
      }
      if (baseColour) out.baseColourImages[i].dataUri = uri;
      continue;
    }
    const std::string decoded = decodeUri(uri);
    if (!baseColour) {
      out.imageUris.insert(decoded);
      continue;
    }
    ImageSource& source = out.baseColourImages[i];
    std::string reason;
    if (!resolveInFolder(folder, uri, decoded, source.file, reason)) {
      source.problem = "its file '" + excerpt(uri) + "' " + reason;
    }
  }
  return true;
}

}  // namespace

std::string joinLikeTinygltf(const std::string& dir, const std::string& file) {
  if (dir.empty()) return file;
  return dir.back() == '/' ? dir + file : dir + "/" + file;
}

bool preflight(const std::vector<unsigned char>& bytes, const std::string& baseDir,
               const GltfLimits& limits, Preflight& out, std::string& error) {
  std::string_view text;
  GlbLayout glb;
  if (!jsonText(bytes, text, glb, error) || !jsonIsUtf8(text, error) ||
      !depthWithin(text, kMaxJsonDepth, error) || !jsonWithinBudget(text, limits, error)) {
    return false;
  }
  // Depth is bounded now, so even a recursive parser is safe.
  Json root;
  try {
    root = Json::parse(text.begin(), text.end());
  } catch (const Json::exception& e) {
    error = "invalid JSON: " + excerpt(e.what());
    return false;
  }
  if (!root.is_object()) {
    error = "the JSON is not an object";
    return false;
  }
  if (!checkExtensions(root, out, error) || !indicesValid(root, error)) return false;
  if (!checkArrayFields(root, "accessors", {"bufferView", "byteOffset", "count"}, error) ||
      !checkArrayFields(root, "bufferViews", {"buffer", "byteOffset", "byteLength", "byteStride"},
                        error) ||
      !checkArrayFields(root, "buffers", {"byteLength"}, error) || !integersFit(root, error) ||
      !followsSpecRules(root, error) || !withinBudget(root, limits, error) ||
      !checkBuffers(root, baseDir, isGlb(bytes) ? &glb : nullptr, out, error) ||
      !collectImages(root, baseDir, out, error)) {
    return false;
  }
  const bool meshopt = placeholdMeshoptFallbacks(root, out);
  const bool draco = dropDracoIndices(root);
  if (meshopt || draco) out.rewrittenJson = root.dump();
  return true;
}

std::vector<unsigned char> withJson(const std::vector<unsigned char>& bytes,
                                    const std::string& json) {
  const bool binary = bytes.size() >= 20 && std::memcmp(bytes.data(), "glTF", 4) == 0;
  if (!binary) return std::vector<unsigned char>(json.begin(), json.end());
  std::uint32_t oldChunk = 0, length = 0;
  std::memcpy(&oldChunk, bytes.data() + 12, 4);
  std::memcpy(&length, bytes.data() + 8, 4);
  // Inside the file: preflight checked. Bytes past the GLB's length are not carried over.
  const std::size_t rest = 20 + std::size_t(oldChunk);
  std::string padded = json;
  while (padded.size() % 4 != 0) padded += ' ';
  std::vector<unsigned char> out(bytes.begin(), bytes.begin() + 12);
  const auto put = [&out](std::uint32_t v) {
    const auto* p = reinterpret_cast<const unsigned char*>(&v);
    out.insert(out.end(), p, p + 4);
  };
  put(static_cast<std::uint32_t>(padded.size()));
  put(0x4E4F534Au);  // "JSON"
  out.insert(out.end(), padded.begin(), padded.end());
  out.insert(out.end(), bytes.begin() + static_cast<std::ptrdiff_t>(rest),
             bytes.begin() + static_cast<std::ptrdiff_t>(length));
  const std::uint32_t total = static_cast<std::uint32_t>(out.size());
  std::memcpy(out.data() + 8, &total, 4);
  return out;
}

}  // namespace ocean_scene::gltf
