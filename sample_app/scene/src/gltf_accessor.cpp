#include "gltf_accessor.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace ocean_scene::gltf {

namespace {

// An accessor with no bufferView is all zeros plus its sparse values; its size is then not
// bounded by any buffer, so it is bounded here.
constexpr std::size_t kMaxSparseOnlyCount = std::size_t{1} << 24;

// Where an accessor's elements are, after every range check has passed.
struct ElementSpan {
  const unsigned char* first = nullptr;
  std::size_t stride = 0;
  std::size_t count = 0;
  int componentType = 0;
};

std::string accessorName(int index, const std::string& what) {
  return "accessor " + std::to_string(index) + " (" + what + ")";
}

const char* typeName(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR:
      return "SCALAR";
    case TINYGLTF_TYPE_VEC2:
      return "VEC2";
    case TINYGLTF_TYPE_VEC3:
      return "VEC3";
    case TINYGLTF_TYPE_VEC4:
      return "VEC4";
    default:
      return "non-vector";
  }
}

// Sizes come from the file, so every sum and product is checked before it could wrap.
bool resolve(const tinygltf::Model& model, int index, const std::string& what, ElementSpan& span,
             std::string& error) {
  const std::string name = accessorName(index, what);
  if (index < 0 || static_cast<std::size_t>(index) >= model.accessors.size()) {
    error = name + " does not exist";
    return false;
  }
  const tinygltf::Accessor& accessor = model.accessors[static_cast<std::size_t>(index)];
  if (accessor.bufferView < 0 && accessor.sparse.isSparse) {
    span.first = nullptr;  // all zeros until the sparse values are applied
    span.stride = 0;
    span.count = accessor.count;
    span.componentType = accessor.componentType;
    if (accessor.count == 0 || accessor.count > kMaxSparseOnlyCount) {
      error = name + " has count " + std::to_string(accessor.count) + " with no bufferView";
      return false;
    }
    return true;
  }
  if (accessor.bufferView < 0 ||
      static_cast<std::size_t>(accessor.bufferView) >= model.bufferViews.size()) {
    error = name + " has no valid bufferView (" + std::to_string(accessor.bufferView) + ")";
    return false;
  }
  const tinygltf::BufferView& view =
      model.bufferViews[static_cast<std::size_t>(accessor.bufferView)];
  if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= model.buffers.size()) {
    error = name + ": bufferView " + std::to_string(accessor.bufferView) +
            " refers to missing buffer " + std::to_string(view.buffer);
    return false;
  }
  const std::vector<unsigned char>& data =
      model.buffers[static_cast<std::size_t>(view.buffer)].data;
  if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset) {
    error = name + ": bufferView " + std::to_string(accessor.bufferView) + " (offset " +
            std::to_string(view.byteOffset) + ", length " + std::to_string(view.byteLength) +
            ") exceeds its buffer of " + std::to_string(data.size()) + " bytes";
    return false;
  }
  const int componentSize =
      tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(accessor.componentType));
  const int components =
      tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(accessor.type));
  if (componentSize <= 0 || components <= 0) {
    error = name + " has an invalid componentType or type";
    return false;
  }
  const auto elementSize = static_cast<std::size_t>(componentSize * components);
  const std::size_t stride = view.byteStride == 0 ? elementSize : view.byteStride;
  if (stride < elementSize) {
    error = name + ": byteStride " + std::to_string(stride) + " is smaller than the element size " +
            std::to_string(elementSize);
    return false;
  }
  if (stride % static_cast<std::size_t>(componentSize) != 0) {
    error = name + ": byteStride " + std::to_string(stride) +
            " is not a multiple of the component size " + std::to_string(componentSize);
    return false;
  }
  if (accessor.count == 0) {
    error = name + " has count 0";
    return false;
  }
  // Last element's end: byteOffset + stride * (count - 1) + elementSize <= byteLength.
  const std::size_t limit = view.byteLength;
  const bool overflow = accessor.byteOffset > limit || elementSize > limit - accessor.byteOffset ||
                        (accessor.count - 1) > (limit - accessor.byteOffset - elementSize) / stride;
  if (overflow) {
    error = name + " is out of bounds: offset " + std::to_string(accessor.byteOffset) + " + " +
            std::to_string(accessor.count) + " elements of stride " + std::to_string(stride) +
            " exceed bufferView " + std::to_string(accessor.bufferView) + " length " +
            std::to_string(limit);
    return false;
  }
  span.first = data.data() + view.byteOffset + accessor.byteOffset;
  span.stride = stride;
  span.count = accessor.count;
  span.componentType = accessor.componentType;
  return true;
}

// Where `bytes` bytes at `offset` into buffer view `viewIndex` are, after every range check.
bool viewBytes(const tinygltf::Model& model, int viewIndex, std::size_t offset, std::size_t bytes,
               const std::string& name, const unsigned char*& first, std::string& error) {
  if (viewIndex < 0 || static_cast<std::size_t>(viewIndex) >= model.bufferViews.size()) {
    error = name + " refers to missing bufferView " + std::to_string(viewIndex);
    return false;
  }
  const tinygltf::BufferView& view = model.bufferViews[static_cast<std::size_t>(viewIndex)];
  if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= model.buffers.size()) {
    error = name + ": bufferView " + std::to_string(viewIndex) + " refers to missing buffer";
    return false;
  }
  const auto& data = model.buffers[static_cast<std::size_t>(view.buffer)].data;
  if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset ||
      offset > view.byteLength || bytes > view.byteLength - offset) {
    error = name + " is out of bounds of bufferView " + std::to_string(viewIndex);
    return false;
  }
  first = data.data() + view.byteOffset + offset;
  return true;
}

double component(const unsigned char* p, int componentType) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
      return static_cast<double>(static_cast<std::int8_t>(*p));
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return static_cast<double>(*p);
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
      std::int16_t v;
      std::memcpy(&v, p, sizeof v);
      return v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
      std::uint16_t v;
      std::memcpy(&v, p, sizeof v);
      return v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
      std::uint32_t v;
      std::memcpy(&v, p, sizeof v);
      return v;
    }
    case TINYGLTF_COMPONENT_TYPE_FLOAT: {
      float v;
      std::memcpy(&v, p, sizeof v);  // glTF only promises alignment relative to the buffer
      return v;
    }
    default:
      return 0.0;
  }
}

// glTF's normalised-integer decoding (spec 3.11): signed values clamp at -1.
double normalise(double raw, int componentType) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
      return std::max(raw / 127.0, -1.0);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return raw / 255.0;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
      return std::max(raw / 32767.0, -1.0);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return raw / 65535.0;
    default:
      return raw;
  }
}

// Sparse substitution (spec 3.6.2.3): strictly increasing indices into the accessor.
bool applySparse(const tinygltf::Model& model, const tinygltf::Accessor& accessor,
                 const std::string& name, std::size_t components, std::vector<double>& raw,
                 std::string& error) {
  const auto& sparse = accessor.sparse;
  if (!sparse.isSparse) return true;
  if (sparse.count < 1 || static_cast<std::size_t>(sparse.count) > accessor.count) {
    error = name + " sparse count " + std::to_string(sparse.count) + " is not in [1, count]";
    return false;
  }
  const auto count = static_cast<std::size_t>(sparse.count);
  const int indexSize =
      tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(sparse.indices.componentType));
  if (sparse.indices.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
      sparse.indices.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
      sparse.indices.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT) {
    error = name + " sparse indices must be unsigned byte, short or int";
    return false;
  }
  const int componentSize =
      tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(accessor.componentType));
  const unsigned char* indices = nullptr;
  const unsigned char* values = nullptr;
  if (sparse.indices.byteOffset < 0 || sparse.values.byteOffset < 0 ||
      !viewBytes(
          model, sparse.indices.bufferView, static_cast<std::size_t>(sparse.indices.byteOffset),
          count * static_cast<std::size_t>(indexSize), name + " sparse indices", indices, error) ||
      !viewBytes(model, sparse.values.bufferView,
                 static_cast<std::size_t>(sparse.values.byteOffset),
                 count * components * static_cast<std::size_t>(componentSize),
                 name + " sparse values", values, error)) {
    if (error.empty()) error = name + " has a negative sparse byteOffset";
    return false;
  }
  double previous = -1.0;
  for (std::size_t i = 0; i < count; ++i) {
    const double target =
        component(indices + i * static_cast<std::size_t>(indexSize), sparse.indices.componentType);
    if (target <= previous || target >= static_cast<double>(accessor.count)) {
      error = name + " sparse index " + std::to_string(static_cast<std::uint64_t>(target)) +
              " is out of range or not increasing";
      return false;
    }
    previous = target;
    for (std::size_t c = 0; c < components; ++c) {
      raw[static_cast<std::size_t>(target) * components + c] =
          component(values + (i * components + c) * static_cast<std::size_t>(componentSize),
                    accessor.componentType);
    }
  }
  return true;
}

// Every component of the accessor as read from the file (before normalisation), sparse
// values applied and the file's min/max checked: values outside the bounds the file declares
// are corrupt (a spike), not geometry.
bool readRaw(const tinygltf::Model& model, int index, const std::string& what,
             std::vector<double>& raw, std::string& error) {
  ElementSpan span;
  if (!resolve(model, index, what, span, error)) return false;
  const std::string name = accessorName(index, what);
  const tinygltf::Accessor& accessor = model.accessors[static_cast<std::size_t>(index)];
  const auto components = static_cast<std::size_t>(
      tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(accessor.type)));
  const auto componentSize = static_cast<std::size_t>(
      tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(accessor.componentType)));
  raw.assign(span.count * components, 0.0);
  if (span.first != nullptr) {
    for (std::size_t i = 0; i < span.count; ++i) {
      for (std::size_t c = 0; c < components; ++c) {
        raw[i * components + c] =
            component(span.first + i * span.stride + c * componentSize, span.componentType);
      }
    }
  }
  if (!applySparse(model, accessor, name, components, raw, error)) return false;
  const auto& lo = accessor.minValues;
  const auto& hi = accessor.maxValues;
  for (std::size_t c = 0; c < components; ++c) {
    const bool hasLo = lo.size() == components, hasHi = hi.size() == components;
    if (!hasLo && !hasHi) break;
    // Exporters print bounds in decimal; a relative 1e-5 absorbs that rounding, not a spike.
    const double scale =
        std::max({1.0, hasLo ? std::abs(lo[c]) : 0.0, hasHi ? std::abs(hi[c]) : 0.0});
    const double slack = 1e-5 * scale;
    for (std::size_t i = 0; i < span.count; ++i) {
      const double v = raw[i * components + c];
      if ((hasLo && v < lo[c] - slack) || (hasHi && v > hi[c] + slack)) {
        error = name + " element " + std::to_string(i) + " component " + std::to_string(c) +
                " is " + std::to_string(v) + ", outside the accessor's min/max [" +
                (hasLo ? std::to_string(lo[c]) : "-") + ", " +
                (hasHi ? std::to_string(hi[c]) : "-") + "]";
        return false;
      }
    }
  }
  return true;
}

bool isQuantizedType(int componentType) {
  return componentType == TINYGLTF_COMPONENT_TYPE_BYTE ||
         componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
         componentType == TINYGLTF_COMPONENT_TYPE_SHORT ||
         componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
}

}  // namespace

bool readFloats(const tinygltf::Model& model, int accessorIndex, const std::string& what, int type,
                bool quantizationAllowed, std::vector<float>& out, std::string& error) {
  if (accessorIndex < 0 || static_cast<std::size_t>(accessorIndex) >= model.accessors.size()) {
    error = accessorName(accessorIndex, what) + " does not exist";
    return false;
  }
  const tinygltf::Accessor& accessor = model.accessors[static_cast<std::size_t>(accessorIndex)];
  const bool isFloat =
      accessor.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT && !accessor.normalized;
  if (accessor.type != type || !(isFloat || isQuantizedType(accessor.componentType))) {
    error = accessorName(accessorIndex, what) + " must be " + typeName(type) + " FLOAT, found " +
            typeName(accessor.type) + " component type " + std::to_string(accessor.componentType);
    return false;
  }
  if (!isFloat && !quantizationAllowed) {
    error = accessorName(accessorIndex, what) + " is quantized (component type " +
            std::to_string(accessor.componentType) +
            ") but the file does not declare KHR_mesh_quantization";
    return false;
  }
  std::vector<double> raw;
  if (!readRaw(model, accessorIndex, what, raw, error)) return false;
  out.resize(raw.size());
  for (std::size_t i = 0; i < raw.size(); ++i) {
    out[i] = static_cast<float>(accessor.normalized ? normalise(raw[i], accessor.componentType)
                                                    : raw[i]);
  }
  return true;
}

bool readVec3(const tinygltf::Model& model, int accessorIndex, const std::string& what,
              bool quantizationAllowed, std::vector<glm::vec3>& out, std::string& error) {
  std::vector<float> values;
  if (!readFloats(model, accessorIndex, what, TINYGLTF_TYPE_VEC3, quantizationAllowed, values,
                  error)) {
    return false;
  }
  out.resize(values.size() / 3);
  static_assert(sizeof(glm::vec3) == 3 * sizeof(float), "vec3 must be packed");
  std::memcpy(out.data(), values.data(), out.size() * sizeof(glm::vec3));
  return true;
}

bool readIndices(const tinygltf::Model& model, int accessorIndex, std::vector<std::uint32_t>& out,
                 std::string& error) {
  if (accessorIndex < 0 || static_cast<std::size_t>(accessorIndex) >= model.accessors.size()) {
    error = accessorName(accessorIndex, "indices") + " does not exist";
    return false;
  }
  const tinygltf::Accessor& accessor = model.accessors[static_cast<std::size_t>(accessorIndex)];
  if (accessor.type != TINYGLTF_TYPE_SCALAR) {
    error = accessorName(accessorIndex, "indices") + " must be SCALAR, found " +
            typeName(accessor.type);
    return false;
  }
  if (accessor.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
      accessor.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
      accessor.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT) {
    error = accessorName(accessorIndex, "indices") +
            " must be UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT, found component type " +
            std::to_string(accessor.componentType);
    return false;
  }
  std::vector<double> raw;
  if (!readRaw(model, accessorIndex, "indices", raw, error)) return false;
  out.resize(raw.size());
  for (std::size_t i = 0; i < raw.size(); ++i) out[i] = static_cast<std::uint32_t>(raw[i]);
  return true;
}

}  // namespace ocean_scene::gltf
