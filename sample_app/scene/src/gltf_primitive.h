#pragma once
// glTF primitive -> ocean_scene::Mesh (private to the loader).

#include <string>

#include <tiny_gltf.h>

#include "scene/model.h"

namespace ocean_scene::gltf {

// Validates and converts one triangle primitive. `notes` collects non-fatal repairs.
bool readPrimitive(const tinygltf::Model& model, const tinygltf::Primitive& primitive, Mesh& out,
                   std::string& error, std::string& notes);

}  // namespace ocean_scene::gltf
