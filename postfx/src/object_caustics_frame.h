#pragma once
// The object caustics' sun view for one frame, fitted to the casters in double precision, and
// the uniform block built from it. CPU only: shared by the pass, the skip test and the tests.
#include <glm/glm.hpp>

#include <postfx/postfx.h>

#include "shared/common.h"  // before the namespace: it includes GLM

namespace postfx {
#include "shared/postfx_object_caustics.h"
#include "shared/postfx_object_caustics_block.h"
}  // namespace postfx

namespace postfx::detail {

struct ObjectLightFrame {
  glm::dvec3 anchor{0.0};                // world: snapped centre of the casters' sun footprint
  glm::dvec3 direction{0.0, -1.0, 0.0};  // unit: where the light travels (refracted under water)
  glm::dvec3 right{1.0, 0.0, 0.0}, up{0.0, 0.0, 1.0};  // unit map axes, perpendicular to it
  double halfGrid = 1.0;                               // half side of the ray grid's region (m)
  double halfMap = 2.0;                                // half side of the caustic map's region (m)
  double zNear = -1.0, zFar = 1.0;  // caster depth range along `direction`, anchor-relative (m)
  bool underwater = false;          // casters below the water level: light refracted by water
  double outerIor = 1.0;            // IOR around the casters (water or air)
};

// Fits the frame to the casters' world bounds: side quantised to 1/8 octaves and centre snapped
// to the ray grid's cell, so the rays stay put while the casters move less than a cell.
ObjectLightFrame fitObjectLightFrame(const FrameDesc& frame);

// The per-caster matrices the caster maps are drawn with, in float: model -> anchor-relative
// world, and the normal matrix (model -> world).
glm::mat4 casterModelToAnchor(const ObjectLightFrame& light, const CasterMesh& mesh);
glm::mat4 casterNormalToWorld(const CasterMesh& mesh);
// Whether every caster's two matrices are finite in float (a finite double transform with
// entries past 3.4e38, or a tiny scale whose inverse is, would reach the GPU as Inf).
bool casterMatricesFinite(const FrameDesc& frame, const ObjectLightFrame& light);

// World bounds (min, max) of every caster's model bounds under its transform.
void casterWorldBounds(const ObjectCausticsFrame& objects, glm::dvec3& lo, glm::dvec3& hi);

// Whether any caster overlaps the receiver map's view (else nothing can land: skip); false
// too when the casters' world bounds are not finite.
bool castersInReceiverView(const ObjectCausticsFrame& objects);

shared::ObjectCausticsBlock buildObjectCausticsBlock(const CreateDesc& create,
                                                     const FrameDesc& frame,
                                                     const ObjectLightFrame& light, int width,
                                                     int height);

// The map's placement for ObjectCausticMap.
ObjectCausticMap describeObjectCausticMap(const ObjectLightFrame& light, int mapSize);

}  // namespace postfx::detail
