#pragma once
// The object caustics' sun view for one frame, fitted to the casters in double precision, and
// the uniform block built from it. CPU only: shared by the pass, the skip test and the tests.
#include <cstdint>

#include <glm/glm.hpp>

#include <postfx/postfx.h>

#include "shared/common.h"  // before the namespace: it includes GLM

namespace postfx {
#include "postfx/object_caustics/postfx_object_caustics.h"
#include "postfx/object_caustics/postfx_object_caustics_block.h"
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
  // A local light (object_caustics_light_frame.h): a perspective view from `position`
  // along `direction` (its axis). zNear/zFar are then distances from the light along the axis;
  // tanHalfGrid and tanHalfMap the half sides of the grid's and the map's frusta at unit
  // distance.
  int light = -1;  // index into ObjectCausticsFrame::lights; -1: the sun
  glm::dvec3 position{0.0};
  double tanHalfGrid = 0.0, tanHalfMap = 0.0;
  std::uint64_t casters = ~std::uint64_t(0);  // bit c: caster c is drawn (within the light's reach)
  bool local() const { return light >= 0; }
};

// Light-space axes that depend on the direction only (not on the casters), so that a caster
// moving does not rotate the map under it.
void lightAxes(const glm::dvec3& direction, glm::dvec3& right, glm::dvec3& up);

// A local light at or below the water level is under water (its rays start in the water).
bool localLightUnderwater(const FrameDesc& frame, const LocalLight& light);

// Fits the frame to the world bounds of the casters that reach the receiver map (all of them
// when none does): side quantised to 1/8 octaves and centre snapped to the ray grid's cell, so
// the rays stay put while the casters move less than a cell.
ObjectLightFrame fitObjectLightFrame(const FrameDesc& frame);

// The per-caster matrices the caster maps are drawn with, in float: model -> anchor-relative
// world, and the normal matrix (model -> world).
glm::mat4 casterModelToAnchor(const ObjectLightFrame& light, const CasterMesh& mesh);
glm::mat4 casterNormalToWorld(const CasterMesh& mesh);
// Whether every caster's two matrices are finite in float (a finite double transform with
// entries past 3.4e38, or a tiny scale whose inverse is, would reach the GPU as Inf).
bool casterMatricesFinite(const FrameDesc& frame, const ObjectLightFrame& light);

// World bounds (min, max) of every caster's model bounds under its transform (of those whose
// bit is set in `casters`).
void casterWorldBounds(const ObjectCausticsFrame& objects, glm::dvec3& lo, glm::dvec3& hi,
                       std::uint64_t casters = ~std::uint64_t(0));
// World position of corner i (0..7) of caster c's model bounds.
glm::dvec3 casterWorldCorner(const CasterMesh& mesh, int i);

// Whether any caster (with its bit set) overlaps the receiver map's view (else nothing can land:
// skip); false too when the casters' world bounds are not finite.
bool castersInReceiverView(const ObjectCausticsFrame& objects);
bool castersInReceiverView(const ObjectCausticsFrame& objects, const SunShadowMap& receivers,
                           std::uint64_t casters);

// Whether the volume caustics draw this frame (Feature::VolumeCaustics, the volume's setting on,
// light to scatter: the god rays' phase and some scattering); the rays' segments are then
// written and each light's view draws them.
bool volumeCausticsOn(const CreateDesc& create, const FrameDesc& frame);

// The block of the sun's view, or of a local light's (light.local()).
shared::ObjectCausticsBlock buildObjectCausticsBlock(const CreateDesc& create,
                                                     const FrameDesc& frame,
                                                     const ObjectLightFrame& light, int width,
                                                     int height);

// World -> a local light's caustic-map clip (testing.h's lightCausticMap).
glm::dmat4 localLightMapClip(const ObjectLightFrame& light);

// The map's placement for ObjectCausticMap.
ObjectCausticMap describeObjectCausticMap(const ObjectLightFrame& light, int mapSize);

}  // namespace postfx::detail
