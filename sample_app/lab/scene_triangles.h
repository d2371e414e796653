#pragma once
// The scene's triangles in world space, placed exactly as GpuScene draws them (instance
// transform, normals by its inverse transpose), for the traced reference's ray queries.
#include <vector>

#include <scene/model.h>

#include "caster_light_path.h"
#include "embree_scene.h"

namespace ocean {

std::vector<reference::TriangleMesh> sceneTriangles(const ocean_scene::Model& model);

// Per mesh of sceneTriangles(model): the plugin's material of each instance GpuScene hands to
// the object caustics as a caster (casterMaterial), none for the others.
reference::CasterMaterials sceneCasterMaterials(const ocean_scene::Model& model);

}  // namespace ocean
