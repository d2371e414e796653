#include "gltf_hostile_corpus.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>

#include "gltf_compressed_files.h"
#include "gltf_test_files.h"
#include "gltf_texture_files.h"

namespace gltf_hostile_corpus {

namespace {

using gltf_test_files::TriangleJson;

Bytes bytesOf(const std::string& text) {
  return Bytes(text.begin(), text.end());
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

// A UV sphere of radius 1: (rings + 1) x (segments + 1) float positions, then
// 2 x segments x rings u32 triangles.
struct Sphere {
  Bytes bytes;
  std::size_t positionBytes = 0;
  int vertices = 0, corners = 0;
};

Sphere sphere(int segments, int rings) {
  std::vector<float> p;
  for (int r = 0; r <= rings; ++r) {
    for (int s = 0; s <= segments; ++s) {
      const double theta = M_PI * r / rings, phi = 2.0 * M_PI * s / segments;
      p.insert(p.end(), {float(std::sin(theta) * std::cos(phi)), float(std::cos(theta)),
                         float(std::sin(theta) * std::sin(phi))});
    }
  }
  std::vector<std::uint32_t> i;
  for (int r = 0; r < rings; ++r) {
    for (int s = 0; s < segments; ++s) {
      const std::uint32_t a = std::uint32_t(r * (segments + 1) + s), b = a + segments + 1;
      i.insert(i.end(), {a, b, a + 1, a + 1, b, b + 1});
    }
  }
  Sphere out;
  out.bytes = gltf_test_files::bytesOf(p);
  out.positionBytes = out.bytes.size();
  out.vertices = int(p.size() / 3);
  out.corners = int(i.size());
  const auto* raw = reinterpret_cast<const unsigned char*>(i.data());
  out.bytes.insert(out.bytes.end(), raw, raw + i.size() * 4);
  return out;
}

// The sphere's glTF with `primitives` (the mesh's array) and `nodes`; `translations` adds
// that many EXT_mesh_gpu_instancing translations as accessor 2 (0: none).
std::string sphereGltf(const Sphere& s, int translations, const std::string& primitives,
                       const std::string& nodes, const std::string& sceneNodes) {
  Bytes data = s.bytes;
  const std::size_t translationOffset = data.size();
  for (int k = 0; k < translations; ++k) {
    const Bytes t = gltf_test_files::bytesOf({float(k % 64) * 3.0f, 0.0f, float(k / 64) * 3.0f});
    data.insert(data.end(), t.begin(), t.end());
  }
  const auto n = [](std::size_t v) { return std::to_string(v); };
  std::string json = R"({"asset": {"version": "2.0"},)";
  if (translations > 0) json += R"( "extensionsUsed": ["EXT_mesh_gpu_instancing"],)";
  json += R"( "buffers": [{"uri": "data:application/octet-stream;base64,)" +
          gltf_test_files::base64(data) + R"(", "byteLength": )" + n(data.size()) +
          R"(}], "bufferViews": [{"buffer": 0, "byteLength": )" + n(s.positionBytes) +
          R"(}, {"buffer": 0, "byteOffset": )" + n(s.positionBytes) + R"(, "byteLength": )" +
          n(std::size_t(s.corners) * 4) + "}";
  if (translations > 0) {
    json += R"(, {"buffer": 0, "byteOffset": )" + n(translationOffset) + R"(, "byteLength": )" +
            n(std::size_t(translations) * 12) + "}";
  }
  json += R"(], "accessors": [{"bufferView": 0, "componentType": 5126, "count": )" +
          n(std::size_t(s.vertices)) +
          R"(, "type": "VEC3", "min": [-1, -1, -1], "max": [1, 1, 1]}, {"bufferView": 1, )" +
          R"("componentType": 5125, "count": )" + n(std::size_t(s.corners)) +
          R"(, "type": "SCALAR"})";
  if (translations > 0) {
    json += R"(, {"bufferView": 2, "componentType": 5126, "count": )" +
            n(std::size_t(translations)) + R"(, "type": "VEC3"})";
  }
  json += R"(], "meshes": [{"name": "sphere", "primitives": [)" + primitives +
          R"(]}], "nodes": [)" + nodes + "]";
  if (!sceneNodes.empty())
    json += R"(, "scenes": [{"nodes": [)" + sceneNodes + R"(]}], "scene": 0)";
  return json + "}";
}

// `item` repeated `count` times, comma-separated; `{i}` in it becomes the index.
std::string repeated(const std::string& item, int count) {
  std::string out;
  const std::size_t at = item.find("{i}");
  out.reserve(std::size_t(count) * (item.size() + 8));
  for (int i = 0; i < count; ++i) {
    if (i > 0) out += ", ";
    out += at == std::string::npos ? item : replaced(item, "{i}", std::to_string(i));
  }
  return out;
}

void patch32(Bytes& bytes, std::size_t at, std::uint32_t value) {
  for (int k = 0; k < 4; ++k)
    bytes[at + std::size_t(k)] = static_cast<unsigned char>(value >> (8 * k));
}

std::uint32_t read32(const Bytes& bytes, std::size_t at) {
  std::uint32_t v = 0;
  std::memcpy(&v, bytes.data() + at, 4);
  return v;
}

Case refused(const std::string& name, const std::string& model, Bytes bytes,
             const std::string& mentions) {
  return Case{name, model, {{model, std::move(bytes)}}, mentions, ""};
}

Case loads(const std::string& name, const std::string& model, Bytes bytes,
           const std::string& notes = "") {
  return Case{name, model, {{model, std::move(bytes)}}, "", notes};
}

// The triangle GLB with one 32-bit field set: the container's damage, field by field.
Case glbField(const std::string& name, std::size_t at, std::uint32_t value,
              const std::string& mentions) {
  Bytes glb = gltf_test_files::triangleGlb();
  patch32(glb, at, value);
  return refused(name, "t.glb", glb, mentions);
}

void addGlbCases(std::vector<Case>& cases) {
  const Bytes glb = gltf_test_files::triangleGlb();
  const std::size_t jsonEnd = 20 + read32(glb, 12);
  // Cut short at each part of the container: tinygltf said "Invalid glTF binary." to all.
  for (std::size_t cut : {std::size_t(2), std::size_t(8), std::size_t(12), std::size_t(19),
                          jsonEnd / 2, jsonEnd, jsonEnd + 4, jsonEnd + 20, glb.size() - 1}) {
    Bytes part(glb.begin(), glb.begin() + long(cut));
    const std::string mentions = cut < 4    ? "not a glTF file"
                                 : cut < 12 ? "GLB header cut short"
                                            : "(byte 8) is";
    cases.push_back(refused("glb_cut_" + std::to_string(cut), "t.glb", part, mentions));
  }
  cases.push_back(glbField("glb_version", 4, 1, "GLB version (byte 4) is 1"));
  cases.push_back(glbField("glb_length_short", 8, 16, "GLB length (byte 8) is 16"));
  cases.push_back(glbField("glb_json_length_zero", 12, 0, "JSON chunk's length (byte 12) is 0"));
  cases.push_back(
      glbField("glb_json_past_end", 12, std::uint32_t(glb.size()), "past the GLB's length"));
  cases.push_back(glbField("glb_json_type", 16, 0x41414141u, "first chunk's type (byte 16)"));
  // tinygltf: "Invalid type for chunk1 data."
  cases.push_back(glbField("glb_bin_type", jsonEnd + 4, 0x58585858u,
                           "second chunk's type (byte " + std::to_string(jsonEnd + 4) + ")"));
  cases.push_back(glbField("glb_bin_unaligned", jsonEnd, 37, "positive multiple of 4"));
  // A BIN length reaching 8 bytes past the GLB's end, which tinygltf's own check lets through.
  cases.push_back(glbField("glb_bin_past_end", jsonEnd, std::uint32_t(glb.size() - jsonEnd),
                           "BIN chunk's length (byte " + std::to_string(jsonEnd) + ")"));
  cases.push_back(glbField("glb_chunk_header_cut", 8, std::uint32_t(jsonEnd + 4),
                           "chunk header at byte " + std::to_string(jsonEnd) + " cut short"));
  // The GLB's length ends it after the JSON, its BIN chunk left behind: tinygltf said "...or
  // GLB with empty BIN chunk".
  cases.push_back(glbField("glb_bin_outside_length", 8, std::uint32_t(jsonEnd),
                           "so it is the BIN chunk, but the GLB has none"));
  TriangleJson longer;
  longer.binChunk = true;
  const std::string json = replaced(longer.text(), "\"byteLength\": 36}], \"bufferViews\"",
                                    "\"byteLength\": 400}], \"bufferViews\"");
  cases.push_back(refused("glb_buffer_longer_than_bin", "t.glb",
                          gltf_test_files::glb(json, longer.data),
                          "byteLength 400 exceeds the BIN chunk's 36 bytes"));
}

void addDataUriCases(std::vector<Case>& cases) {
  // 1 MB of base64 with one bad character deep inside: the message says where, and nothing of
  // the URI itself.
  Bytes payload(750000, 0x5a);
  std::string base64 = gltf_test_files::base64(payload);
  base64[600000] = '!';
  TriangleJson bad;
  bad.data = payload;
  bad.buffer = "\"uri\": \"data:application/octet-stream;base64," + base64 + "\"";
  cases.push_back(
      refused("data_uri_bad_base64", "t.gltf", bytesOf(bad.text()),
              "data: URI (1000037 bytes) has '!' (0x21) at character 600000 of its base64"));
  TriangleJson media;
  media.buffer = "\"uri\": \"data:text/plain;base64," +
                 gltf_test_files::base64(gltf_test_files::trianglePositions()) + "\"";
  cases.push_back(
      refused("data_uri_media_type", "t.gltf", bytesOf(media.text()), "media type 'text/plain'"));
  TriangleJson size;
  size.buffer = "\"uri\": \"data:application/octet-stream;base64," +
                gltf_test_files::base64(Bytes(32, 0)) + "\"";
  cases.push_back(refused("data_uri_size", "t.gltf", bytesOf(size.text()),
                          "decodes to 32 bytes, byteLength says 36"));
  TriangleJson plain;
  plain.buffer = "\"uri\": \"data:application/octet-stream,AAAA\"";
  cases.push_back(refused("data_uri_not_base64", "t.gltf", bytesOf(plain.text()), "is not base64"));
  TriangleJson image;
  image.top = "\"images\": [{\"uri\": \"data:image/png;base64,iVBO#RK\"}], ";
  cases.push_back(refused("data_uri_image", "t.gltf", bytesOf(image.text()),
                          "image 0 data: URI (29 bytes) has '#' (0x23) at character 4"));
}

void addNameCases(std::vector<Case>& cases) {
  const std::string name(1 << 20, 'n');
  TriangleJson points;
  points.primitive = "\"mode\": 0";
  cases.push_back(
      refused("long_mesh_name", "t.gltf",
              bytesOf(replaced(points.text(), "\"name\": \"tri\"", "\"name\": \"" + name + "\"")),
              "(1048576 bytes)' primitive 0: primitive mode 0 (points)"));
  TriangleJson matrix;
  matrix.nodes = "{\"mesh\": 0, \"name\": \"" + name + "\", \"matrix\": [1, 0, 0]}";
  cases.push_back(refused("long_node_name", "t.gltf", bytesOf(matrix.text()),
                          "(1048576 bytes)' matrix does not have 16 elements"));
  TriangleJson bounds;
  bounds.accessor = "";
  cases.push_back(
      loads("long_mesh_name_note", "t.gltf",
            bytesOf(replaced(bounds.text(), "\"name\": \"tri\"", "\"name\": \"" + name + "\"")),
            "(1048576 bytes)': POSITION accessor 0 has no min/max"));
  // tinygltf's own error quotes the image's name whole (an image with neither a uri nor a
  // bufferView: a bufferView "zero" is refused before tinygltf, as an index that is no integer).
  TriangleJson image;
  image.top = "\"images\": [{\"name\": \"" + name + "\"}], ";
  cases.push_back(refused("long_tinygltf_line", "t.gltf", bytesOf(image.text()), "tinygltf: "));
}

void addPathCases(std::vector<Case>& cases) {
  const Bytes triangle = gltf_test_files::trianglePositions();
  const auto withUri = [&](const std::string& uri) {
    TriangleJson json;
    json.buffer = "\"uri\": \"" + uri + "\"";
    return bytesOf(json.text());
  };
  cases.push_back(refused("uri_dot", "t.gltf", withUri("."), "names the model's folder itself"));
  Case inside = loads("uri_dot_dot_inside", "t.gltf", withUri("sub/../tri.bin"));
  inside.files.push_back({"tri.bin", triangle});
  cases.push_back(inside);
  Case outside = refused("uri_dot_dot_outside", "t.gltf", withUri("sub/../../tri.bin"),
                         "leaves the model's folder");
  outside.files.push_back({"tri.bin", triangle});
  cases.push_back(outside);
  Case size = refused("uri_file_size", "t.gltf", withUri("tri.bin"),
                      "uri 'tri.bin' has 40 bytes, byteLength says 36");
  size.files.push_back({"tri.bin", Bytes(40, 0)});
  cases.push_back(size);
}

void addIntegerCases(std::vector<Case>& cases) {
  const std::string rich = [] {
    const Bytes b = gltf_test_files::featureRichModel(false);
    return std::string(b.begin(), b.end());
  }();
  const std::string values = "\"values\": {\"bufferView\": 3}";
  cases.push_back(
      refused("sparse_offset_2p40", "t.gltf",
              bytesOf(replaced(rich, values,
                               "\"values\": {\"bufferView\": 3, \"byteOffset\": 1099511627776}")),
              "accessors[0].sparse.values.byteOffset is 1099511627776"));
  cases.push_back(refused(
      "sparse_offset_2p63", "t.gltf",
      bytesOf(replaced(rich, values,
                       "\"values\": {\"bufferView\": 3, \"byteOffset\": 9223372036854775808}")),
      "accessors[0].sparse.values.byteOffset is 9223372036854775808"));
  cases.push_back(refused(
      "sparse_count_2p31", "t.gltf",
      bytesOf(replaced(rich, "\"sparse\": {\"count\": 1,", "\"sparse\": {\"count\": 2147483648,")),
      "accessors[0].sparse.count is 2147483648"));
  using namespace gltf_compressed_files;
  const Compressed quad = encodeMeshoptQuad();
  const std::string meshopt = meshoptGltf(quad, "");
  const std::string stride = "\"byteStride\": 12, \"count\": 4";
  const auto meshoptCase = [&](const std::string& name, const std::string& with,
                               const std::string& mentions) {
    return refused(name, "t.glb", gltf_test_files::glb(replaced(meshopt, stride, with), quad.bytes),
                   mentions);
  };
  cases.push_back(meshoptCase("meshopt_stride_zero", "\"byteStride\": 0, \"count\": 4",
                              "byteStride 0: ATTRIBUTES needs 4..256"));
  cases.push_back(meshoptCase("meshopt_count_2p31", "\"byteStride\": 12, \"count\": 2147483648",
                              "EXT_meshopt_compression.count is 2147483648"));
  cases.push_back(meshoptCase("meshopt_count_float", "\"byteStride\": 12, \"count\": 1e20",
                              "count is 1e+20; it must be a whole number"));
}

void addTextureCases(std::vector<Case>& cases, const fs::path& scratch) {
  using namespace gltf_texture_files;
  const unsigned char orange[3] = {255, 128, 0};
  const Bytes image = png(scratch / "orange.png", orange);
  // The Duck: one textured model as a .glb, a .gltf with the image beside it and a .gltf with
  // the image in a data: URI; all three must come out the same colour.
  const std::string averaged = "baseColorTexture averaged into its colour";
  cases.push_back(loads("texture_glb", "duck.glb", texturedGlb(image, "[1, 1, 1, 1]"), averaged));
  Case file = loads("texture_file", "duck.gltf", bytesOf(texturedGltf("duck.png", "[1, 1, 1, 1]")),
                    averaged);
  file.files.push_back({"duck.png", image});
  cases.push_back(file);
  cases.push_back(
      loads("texture_data_uri", "duck.gltf",
            bytesOf(texturedGltf("data:image/png;base64," + gltf_test_files::base64(image),
                                 "[1, 1, 1, 1]")),
            averaged));
  // A PNG whose chunks are whole but whose IHDR libpng refuses (bit depth 3): libpng's own
  // line is caught and named, never printed.
  cases.push_back(loads("texture_bad_ihdr", "t.glb",
                        texturedGlb(withIhdrByte(image, 8, 3), "[1, 1, 1, 1]"), "libpng"));
  Case outside =
      loads("texture_outside", "t.gltf", bytesOf(texturedGltf("../orange.png", "[1, 1, 1, 1]")),
            "without baseColorTexture (its file '../orange.png' leaves the model's "
            "folder");
  cases.push_back(outside);
}

// Files that broke a rule of the spec and were accepted, or were refused with a message
// that named the wrong problem (issue 56, items 12 and 16).
void addSpecRuleCases(std::vector<Case>& cases) {
  const auto text = [](const TriangleJson& json) { return bytesOf(json.text()); };
  TriangleJson mesh;
  mesh.nodes = "{\"mesh\": -5}";  // was "the scene has no node with a mesh"
  cases.push_back(refused("index_mesh_negative", "t.gltf", text(mesh),
                          "nodes[0].mesh is -5; an index must be an integer >= 0 (the position "
                          "of an entry of \"meshes\")"));
  mesh.nodes = "{\"mesh\": -0}";  // was drawn as mesh 0, uncounted by the budget
  cases.push_back(refused("index_mesh_minus_zero", "t.gltf", text(mesh), "nodes[0].mesh is -0;"));
  cases.push_back(refused("index_scene_minus_zero", "t.gltf",
                          bytesOf(replaced(TriangleJson{}.text(), "\"scene\": 0", "\"scene\": -0")),
                          "scene is -0; an index must be an integer >= 0"));
  cases.push_back(
      refused("index_attribute_float", "t.gltf",
              bytesOf(replaced(TriangleJson{}.text(), "{\"POSITION\": 0}", "{\"POSITION\": 0.0}")),
              "meshes[0].primitives[0].attributes.POSITION is 0.0; an index must be"));
  // Every node another's child and no scene: was "the scene has no node with a mesh".
  TriangleJson cycle;
  cycle.nodes = "{\"children\": [1]}, {\"mesh\": 0, \"children\": [0]}";
  cases.push_back(
      refused("node_cycle_no_scene", "t.gltf",
              bytesOf(replaced(cycle.text(), ", \"scenes\": [{\"nodes\": [0]}], \"scene\": 0", "")),
              "each of its 2 node(s) is another node's child, so no node is a root"));
  // 70 "nodes" keys: was counted as 70 x 1000 nodes and refused as over the nodes limit.
  TriangleJson duplicate;
  for (int i = 0; i < 69; ++i) duplicate.top += "\"nodes\": [" + repeated("{}", 1000) + "], ";
  cases.push_back(refused("duplicate_nodes_key", "t.gltf", text(duplicate),
                          "duplicate key \"nodes\" in the root object"));
  TriangleJson offset;
  offset.accessor = "\"byteOffset\": -0";  // was "is 0; it must be a non-negative integer"
  cases.push_back(refused("offset_minus_zero", "t.gltf", text(offset),
                          "accessors[0].byteOffset is -0; it must be a non-negative integer, "
                          "written without a sign"));
  // Was tinygltf's "'count' property is not a positive integer", naming no accessor.
  cases.push_back(
      refused("count_exponent", "t.gltf",
              bytesOf(replaced(TriangleJson{}.text(), "\"count\": 3", "\"count\": 2.4e1")),
              "accessors[0].count is 24.0; it must be a non-negative integer written as one (24"));
  // UTF-16 (with and without a byte-order mark): was "unexpected end of input".
  const auto utf16 = [](const std::string& json, bool bom) {
    Bytes out = bom ? Bytes{0xFF, 0xFE} : Bytes{};
    for (char c : json) out.insert(out.end(), {static_cast<unsigned char>(c), 0});
    return out;
  };
  cases.push_back(refused("utf16_bom", "t.gltf", utf16(TriangleJson{}.text(), true),
                          "the JSON is UTF-16 or UTF-32"));
  cases.push_back(
      refused("utf16", "t.gltf", utf16(TriangleJson{}.text(), false), "glTF's JSON must be UTF-8"));
  // Was tinygltf's "accessor[1] invalid bufferView".
  TriangleJson indices;
  indices.accessor =
      "\"min\": [0, 0, -1], \"max\": [1, 0, 0]}, {\"componentType\": 5125, \"count\": 3, "
      "\"type\": \"SCALAR\"";
  indices.primitive = "\"indices\": 1";
  cases.push_back(refused("indices_without_view", "t.gltf", text(indices),
                          "meshes[0].primitives[0].indices is accessors[1], which has no "
                          "bufferView"));
  // Accepted though invalid.
  cases.push_back(refused(
      "asset_version_1", "t.gltf",
      bytesOf(replaced(TriangleJson{}.text(), "\"version\": \"2.0\"", "\"version\": \"1.0\"")),
      "asset.version is \"1.0\"; this loader reads glTF 2.0"));
  cases.push_back(refused(
      "byte_stride_zero", "t.gltf",
      bytesOf(replaced(TriangleJson{}.text(), "\"byteLength\": 36}], \"accessors\"",
                       "\"byteLength\": 36, \"byteStride\": 0}], \"accessors\"")),
      "bufferViews[0].byteStride is 0; when present it must be a multiple of 4 from 4 to 252"));
  TriangleJson factor;
  factor.top = "\"materials\": [{\"pbrMetallicRoughness\": {\"baseColorFactor\": [1]}}], ";
  factor.primitive = "\"material\": 0";
  cases.push_back(refused("base_colour_factor_short", "t.gltf", text(factor),
                          "materials[0].pbrMetallicRoughness.baseColorFactor is 1 value(s); it "
                          "must be 4 numbers"));
  // A second BIN chunk, and an unknown chunk running past the GLB's end.
  const auto withChunk = [](std::uint32_t type, std::uint32_t length, std::uint32_t data) {
    Bytes glb = gltf_test_files::triangleGlb();
    const std::size_t at = glb.size();
    glb.resize(at + 8 + data, 0);
    patch32(glb, at, length);
    patch32(glb, at + 4, type);
    patch32(glb, 8, std::uint32_t(glb.size()));
    return glb;
  };
  const std::size_t end = gltf_test_files::triangleGlb().size();
  cases.push_back(refused("glb_second_bin", "t.glb", withChunk(0x004E4942u, 4, 4),
                          "GLB has a second BIN chunk at byte " + std::to_string(end)));
  cases.push_back(
      refused("glb_chunk_past_end", "t.glb", withChunk(0x41414141u, 100, 4),
              "GLB chunk 0x41414141 ('AAAA') at byte " + std::to_string(end) + " has length 100"));
  cases.push_back(loads("glb_unknown_chunk", "t.glb", withChunk(0x41414141u, 4, 4)));
}

}  // namespace

Bytes manyPrimitives(int primitives) {
  return bytesOf(
      sphereGltf(sphere(32, 16), 0,
                 repeated("{\"attributes\": {\"POSITION\": 0}, \"indices\": 1}", primitives),
                 "{\"mesh\": 0}", "0"));
}

Bytes instancedTriangles(int nodes, int copies) {
  return bytesOf(sphereGltf(
      sphere(100, 50), copies, "{\"attributes\": {\"POSITION\": 0}, \"indices\": 1}",
      repeated("{\"mesh\": 0, \"extensions\": {\"EXT_mesh_gpu_instancing\": {\"attributes\": "
               "{\"TRANSLATION\": 2}}}}",
               nodes),
      repeated("{i}", nodes)));
}

Bytes manyNodes(int nodes) {
  return bytesOf(sphereGltf(sphere(16, 8), 0, "{\"attributes\": {\"POSITION\": 0}, \"indices\": 1}",
                            repeated("{\"mesh\": 0}", nodes), ""));
}

std::vector<Case> corpus(const fs::path& scratch) {
  std::vector<Case> cases;
  cases.push_back(
      refused("amplify_primitives", "sphere.gltf", manyPrimitives(100000), "bytes once expanded"));
  cases.push_back(refused("amplify_triangles", "sphere.gltf", instancedTriangles(250, 4000),
                          "10000000000 triangles after instancing (limit 4194304)"));
  cases.push_back(refused("amplify_instances", "sphere.gltf", manyNodes(1000000),
                          "JSON values (limit 1048576)"));
  cases.push_back(
      refused("amplify_nodes", "sphere.gltf", manyNodes(100000), "100000 nodes (limit 65536)"));
  addGlbCases(cases);
  addDataUriCases(cases);
  addNameCases(cases);
  addPathCases(cases);
  addIntegerCases(cases);
  addTextureCases(cases, scratch);
  addSpecRuleCases(cases);
  return cases;
}

fs::path write(const fs::path& root, const Case& c) {
  const fs::path dir = gltf_test_files::freshDir(root, c.name);
  for (const auto& [name, bytes] : c.files) {
    fs::create_directories((dir / name).parent_path());
    gltf_test_files::writeFile(dir / name, bytes);
  }
  return dir / c.model;
}

}  // namespace gltf_hostile_corpus
