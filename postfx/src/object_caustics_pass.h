#pragma once
// Light-map caustics of refractive and reflective casters (seed 000, section III; seed 003's
// temporal filter), in four steps inside one timed pass:
//   1. caster maps: the casters drawn from the sun (orthographic, fitted), nearest surface and
//      farthest surface, positions + normals (seed 000 step 2);
//   2. splats: one point per grid cell, refracted/reflected, hit found in image space against
//      the host's receiver depth map, Gaussian-splatted additively into the caustic map;
//   3. (optional) temporal filter of the caustic map;
//   4. composite: each host pixel on a receiver reads the map and adds its light.
// Flux per ray: a regular grid in the sun's projection gives every ray the same perpendicular
// area, so each carries E * cellArea (times Fresnel and Beer-Lambert). This is seed 000's eq. 6
// normalisation by the visible projected area V, with V counted by the grid itself (no query,
// no stall); its extra N.L factor is dropped because the grid already samples the projected
// area (keeping it would lose a third of a sphere's light).
#include <epoxy/gl.h>

#include <string>

#include <glkit/handle.h>
#include <glkit/program.h>
#include <postfx/postfx.h>

#include "object_caustics_frame.h"

namespace postfx::detail {

class ObjectCausticsPass {
 public:
  Result init(const std::string& defines, std::string& error);

  // Sizes the maps, attaches the host target, uploads the block. GlError with a message when a
  // framebuffer is incomplete. Call under a GlStateGuard.
  Result prepare(const FrameDesc& frame, const ObjectLightFrame& light,
                 const shared::ObjectCausticsBlock& block, std::string& error);
  // Steps 1-4; call under a GlStateGuard (it adds its own guard for depth/point state).
  void draw(const FrameDesc& frame, int width, int height);

  const ObjectCausticMap& map() const { return map_; }

 private:
  void ensureGrid(int size);
  void ensureMap(int size);
  void ensureLandings(int size, int layers);
  void drawCasterMaps(const FrameDesc& frame);
  void traceRays(const FrameDesc& frame);
  void drawSplats();
  void filterTemporally(const FrameDesc& frame);
  void composite(const FrameDesc& frame, int width, int height);

  glkit::Program caster_, trace_, splat_, temporal_, composite_;
  glkit::VertexArray meshVao_, emptyVao_;
  glkit::Buffer uniformBuffer_;
  glkit::Framebuffer frontFbo_, backFbo_, splatFbo_, temporalFbo_, compositeFbo_;
  glkit::Texture frontPosition_, frontNormal_, backPosition_, backNormal_;
  glkit::Texture casterDepth_;
  glkit::Texture splatMap_, history_[2];
  // Where each ray lands and its flux (object_caustics_trace.comp): 2 layers per colour channel.
  glkit::Texture landings_;
  int landingLayers_ = 0;
  glkit::Sampler pointSampler_, linearSampler_;
  int gridSize_ = 0, mapSize_ = 0;
  int historyIndex_ = 0;
  bool historyValid_ = false;
  bool dispersed_ = false;      // a caster is dispersed this frame: three rays per grid cell
  ObjectCausticMap map_;        // what the last frame published
  ObjectCausticMap placement_;  // this frame's placement (texture filled by draw)
  ObjectLightFrame light_;  // this frame's light-space fit (the casters are drawn relative to it)
};

}  // namespace postfx::detail
