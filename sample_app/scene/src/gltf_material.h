#pragma once
// glTF material -> ocean_scene::Material (private to the loader).

#include <string>

#include <tiny_gltf.h>

#include "scene/model.h"

namespace ocean_scene::gltf {

// Reads the metallic-roughness factors and the KHR_materials_ior / _transmission / _volume
// extensions. Out-of-range or non-finite values are errors (they would poison the caustic
// passes); absent values keep the glTF defaults.
bool readMaterial(const tinygltf::Material& source, Material& out, std::string& error);

}  // namespace ocean_scene::gltf
