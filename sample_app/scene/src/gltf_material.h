#pragma once
// glTF material -> ocean_scene::Material (private to the loader).

#include <string>

#include <tiny_gltf.h>

#include "scene/model.h"

namespace ocean_scene::gltf {

// Reads the metallic-roughness factors and the KHR_materials_ior / _transmission / _volume /
// _dispersion extensions. Out-of-range or non-finite values are errors (they would poison the
// caustic passes); absent values keep the glTF defaults.
bool readMaterial(const tinygltf::Material& source, Material& out, std::string& error);

// The textures `source` refers to, by glTF name ("baseColorTexture, KHR_materials_transmission.
// transmissionTexture"), or "" when none: the sample renders materials from their factors
// (and the base colour texture's mean, when `baseColourUsed`), and says what that leaves out.
std::string ignoredTextures(const tinygltf::Material& source, bool baseColourUsed);

}  // namespace ocean_scene::gltf
