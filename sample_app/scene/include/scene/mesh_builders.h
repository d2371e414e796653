#pragma once
// Procedural mesh primitives. All produce outward unit normals and counter-clockwise winding
// seen from outside; material index 0.

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/model.h"

namespace ocean_scene {

// Unit-radius sphere from a subdivided icosahedron: near-uniform triangles, which keeps the
// noise displacement of rocks free of pole artefacts. subdivisions 0..7.
Mesh makeIcosphere(int subdivisions, const std::string& name);

// Axis-aligned box centred at the origin; each face has its own vertices so face normals are
// exact (a vertical side has a normal with y = 0 exactly).
Mesh makeBox(const glm::vec3& halfExtent, const std::string& name);

// Vertical cylinder from y = y0 to y = y1 with smooth horizontal side normals and flat caps.
Mesh makeCylinder(float radius, float y0, float y1, int segments, const std::string& name);

// Torus around the y axis (lying flat in the xz plane).
Mesh makeTorus(float majorRadius, float minorRadius, int majorSegments, int minorSegments,
               const std::string& name);

// Surface of revolution around the y axis. profile holds (radius, y) points in order; the
// outward side is to the right of the direction of travel in the (r, y) plane, i.e. walk up the
// outside and down the inside. Points with radius 0 close the surface on the axis.
Mesh makeLathe(const std::vector<glm::vec2>& profile, int segments, const std::string& name);

// Area-weighted vertex normals from the triangles; vertices no triangle touches get +y.
void computeSmoothNormals(Mesh& mesh);

// Applies an affine transform to positions and the inverse-transpose to normals, in place.
void transformMesh(Mesh& mesh, const glm::mat4& transform);

// True if every normal is finite and unit length within `tolerance`.
bool normalsAreUnit(const Mesh& mesh, float tolerance = 1e-3f);

}  // namespace ocean_scene
