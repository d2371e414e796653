#pragma once
// Safe lookups in tinygltf's JSON values (extensions the loader reads itself; private to it).

#include <cmath>

#include <tiny_gltf.h>

namespace ocean_scene::gltf {

// object[key], or null when `object` is not an object or has no such member. Value::Get(key)
// asserts on non-objects, so every lookup goes through here.
inline const tinygltf::Value* member(const tinygltf::Value& object, const char* key) {
  if (!object.IsObject() || !object.Has(key)) return nullptr;
  return &object.Get(key);
}

// object[key] as a whole number in [0, 2^53] (exact in a double), `absent` when there is no
// such member, -1 when it is there but not such a number.
inline long long wholeNumber(const tinygltf::Value& object, const char* key, long long absent) {
  const tinygltf::Value* v = member(object, key);
  if (v == nullptr) return absent;
  if (!v->IsNumber()) return -1;
  const double d = v->GetNumberAsDouble();
  if (!(d >= 0.0 && d <= 9007199254740992.0) || d != std::floor(d)) return -1;
  return static_cast<long long>(d);
}

}  // namespace ocean_scene::gltf
