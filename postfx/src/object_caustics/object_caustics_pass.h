#pragma once
// Light-map caustics of refractive and reflective casters ([2], section III; [3]'s
// temporal filter), in four steps inside one timed pass:
//   1. caster maps: the casters drawn from the sun (orthographic, fitted), nearest surface and
//      farthest surface, positions + normals ([2] step 2);
//   2. splats: one point per grid cell, refracted/reflected, hit found in image space against
//      the host's receiver depth map, Gaussian-splatted additively into the caustic map;
//   3. (optional) temporal filter of the caustic map;
//   4. composite: each host pixel on a receiver reads the map and adds its light.
// Flux per ray: a regular grid in the sun's projection gives every ray the same perpendicular
// area, so each carries E * cellArea (times Fresnel and Beer-Lambert). This is [2]'s eq. 6
// normalisation by the visible projected area V, with V counted by the grid itself (no query,
// no stall); its extra N.L factor is dropped because the grid already samples the projected
// area (keeping it would lose a third of a sphere's light).
#include <epoxy/gl.h>

#include <span>
#include <string>
#include <vector>

#include <glkit/handle.h>
#include <glkit/program.h>
#include <postfx/postfx.h>

#include "core/validation.h"
#include "object_caustics/object_caustics_frame.h"

namespace postfx::detail {

// What one frame draws: the sun's view and the local lights' that reach a caster, each with a
// block per camera view (postfx/views.h). The maps are the same for every camera view; only the
// composite's camera constants differ.
struct ObjectCausticsViews {
  bool sun = false;
  ObjectLightFrame sunFrame;
  bool volume = false;  // the volume caustics draw (volumeCausticsOn)
  std::vector<ObjectLightFrame> lights;
  // Camera view v's blocks from v * slotsPerView(): the sun's (slot 0) and light k's (k + 1).
  std::vector<shared::ObjectCausticsBlock> blocks;
  std::size_t slotsPerView() const { return 1 + lights.size(); }
};

// One camera view the composite adds light into: its frame (camera, G-buffer, target) and its
// rectangle in the target.
struct ObjectCausticsTarget {
  const FrameDesc* frame = nullptr;
  ValidatedTextures rect;
};

class ObjectCausticsPass {
 public:
  // maxLocalLights: CreateDesc's; the uniform buffer holds a block for the sun and each light.
  // volume: Feature::VolumeCaustics (its programs are built).
  Result init(const std::string& defines, int maxLocalLights, bool volume, std::string& error);

  // Sizes the maps, checks every camera view's target, uploads the blocks. GlError with a
  // message when a framebuffer is incomplete. Call under a GlStateGuard.
  Result prepare(const FrameDesc& frame, const ObjectCausticsViews& views,
                 std::span<const ObjectCausticsTarget> targets, std::string& error);
  // The pass's own fixed-function state; call under a GlStateGuard and an
  // ObjectCausticsStateGuard, before the draws.
  void setDrawState();
  // Steps 1-3 for the sun's view once, step 4 into every camera view's target; then (each timed
  // on its own) for prepared light k: steps 1 and 2 once and 4 per camera view (a local light's
  // map is not filtered temporally). With the volume caustics, after each view's step 4 the
  // rays' in-scattered light into the same view.
  void drawSun(std::span<const ObjectCausticsTarget> targets);
  void drawLight(std::span<const ObjectCausticsTarget> targets, int k);
  // After the last draw: lets go of the host's target.
  void finishDraws();

  const ObjectCausticMap& map() const { return map_; }
  // The caustic map of the last light drawn (testing.h): its texture and world -> map clip.
  GlName lightMapTexture() const { return lightMap_.id(); }
  int lightMapSize() const { return lightMapSize_; }
  const glm::dmat4& lightMapClip() const { return lightMapClip_; }

 private:
  void ensureGrid(int size);
  void ensureMap(int size);
  void ensureLightMap(int size);
  void ensureLandings(int size, int layers);
  void ensureVolumeLight(int width, int height);
  void bindBlock(int slot);
  void drawCasterMaps(const FrameDesc& frame, const ObjectLightFrame& view);
  void traceRays(GLuint receiverDepth, int iterations);
  void drawSplats(GLuint fbo, int mapSize);
  void filterTemporally(const FrameDesc& frame);
  void composite(const ObjectCausticsTarget& target, GLuint map, GLuint receiverDepth);
  // The rays' in-scattered light into the target composite() just drew into.
  void drawVolume(const ObjectCausticsTarget& target);

  glkit::Program caster_, trace_, splat_, temporal_, composite_;
  // Feature::VolumeCaustics only: the rays drawn as beams, and as lines.
  glkit::Program volumeBeams_, volumeLines_, volumeResolve_;
  // Their light summed in float at the largest view's size, then added to each view's target.
  glkit::Texture volumeLight_;
  glkit::Framebuffer volumeFbo_;
  int volumeWidth_ = 0, volumeHeight_ = 0;
  glkit::VertexArray meshVao_, emptyVao_;
  glkit::Buffer uniformBuffer_;
  GLintptr blockStride_ = 0;       // bytes between the blocks in uniformBuffer_ (offset alignment)
  std::size_t blockCapacity_ = 0;  // blocks uniformBuffer_ holds (grows with the camera views)
  std::size_t slotsPerView_ = 1;   // this frame's ObjectCausticsViews::slotsPerView()
  glkit::Framebuffer frontFbo_, backFbo_, splatFbo_, temporalFbo_, compositeFbo_, lightFbo_;
  glkit::Texture frontPosition_, frontNormal_, backPosition_, backNormal_;
  glkit::Texture casterDepth_;
  glkit::Texture splatMap_, history_[2];
  // The local lights' caustic map, one for all of them (each light splats and composites before
  // the next): allocated the first time a light reaches a caster.
  glkit::Texture lightMap_;
  int lightMapSize_ = 0;
  std::vector<ObjectLightFrame> lights_;  // this frame's lights, as prepared
  glm::dmat4 lightMapClip_{1.0};
  // Where each ray lands and its flux (object_caustics_trace.comp): 2 layers per colour channel.
  glkit::Texture landings_;
  int landingLayers_ = 0;
  glkit::Sampler pointSampler_, linearSampler_;
  int gridSize_ = 0, mapSize_ = 0;
  int historyIndex_ = 0;
  bool historyValid_ = false;
  bool dispersed_ = false;  // a caster is dispersed this frame: three rays per grid cell
  bool volume_ = false;     // the volume caustics draw this frame
  VolumeCausticsMethod volumeMethod_ = VolumeCausticsMethod::Beams;
  ObjectCausticMap map_;        // what the last frame published
  ObjectCausticMap placement_;  // this frame's placement (texture filled by draw)
  ObjectLightFrame light_;  // this frame's light-space fit (the casters are drawn relative to it)
};

}  // namespace postfx::detail
