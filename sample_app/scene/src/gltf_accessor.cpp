#include "gltf_accessor.h"

#include <cstring>

namespace ocean_scene::gltf {

namespace {

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
  if (accessor.sparse.isSparse) {
    error = name + " is sparse, which is not supported";
    return false;
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

}  // namespace

bool readVec3(const tinygltf::Model& model, int accessorIndex, const std::string& what,
              std::vector<glm::vec3>& out, std::string& error) {
  ElementSpan span;
  if (!resolve(model, accessorIndex, what, span, error)) return false;
  const tinygltf::Accessor& accessor = model.accessors[static_cast<std::size_t>(accessorIndex)];
  if (accessor.type != TINYGLTF_TYPE_VEC3 ||
      accessor.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT || accessor.normalized) {
    error = accessorName(accessorIndex, what) + " must be VEC3 FLOAT, found " +
            typeName(accessor.type) + " component type " + std::to_string(accessor.componentType);
    return false;
  }
  out.resize(span.count);
  for (std::size_t i = 0; i < span.count; ++i) {
    // memcpy: glTF only promises 4-byte alignment relative to the buffer start.
    std::memcpy(&out[i], span.first + i * span.stride, sizeof(glm::vec3));
  }
  return true;
}

bool readIndices(const tinygltf::Model& model, int accessorIndex, std::vector<std::uint32_t>& out,
                 std::string& error) {
  ElementSpan span;
  if (!resolve(model, accessorIndex, "indices", span, error)) return false;
  const tinygltf::Accessor& accessor = model.accessors[static_cast<std::size_t>(accessorIndex)];
  if (accessor.type != TINYGLTF_TYPE_SCALAR) {
    error = accessorName(accessorIndex, "indices") + " must be SCALAR, found " +
            typeName(accessor.type);
    return false;
  }
  out.resize(span.count);
  for (std::size_t i = 0; i < span.count; ++i) {
    const unsigned char* p = span.first + i * span.stride;
    switch (span.componentType) {
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        out[i] = *p;
        break;
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        std::uint16_t v;
        std::memcpy(&v, p, sizeof v);
        out[i] = v;
        break;
      }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        std::memcpy(&out[i], p, sizeof(std::uint32_t));
        break;
      default:
        error = accessorName(accessorIndex, "indices") +
                " must be UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT, found component type " +
                std::to_string(span.componentType);
        return false;
    }
  }
  return true;
}

}  // namespace ocean_scene::gltf
