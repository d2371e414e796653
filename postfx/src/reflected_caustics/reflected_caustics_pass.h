#pragma once
// The reflected caustics pass (Feature::ReflectedCaustics, Pass::ReflectedCaustics), per view:
// the reflected light field around the view's camera (reflected_field_pass.h), then a
// full-screen triangle that adds its light to the pixels above the water, blended ONE, ONE into
// the host's target through a framebuffer of its own (the seabed pass's carries its raw
// output too). It reads the seabed pass's block, G-buffer, water and shadow units
// (CausticsPass::bindState), so it runs under that state.
#include <epoxy/gl.h>

#include <cstdint>
#include <string>

#include <glkit/handle.h>
#include <glkit/program.h>
#include <postfx/postfx.h>

#include "core/validation.h"
#include "reflected_caustics/reflected_field_pass.h"
#include "reflected_caustics/reflected_receiver_pass.h"

namespace postfx::detail {

struct SeabedInputs;

class ReflectedCausticsPass {
 public:
  Result init(const CreateDesc& desc, std::string& error);
  bool ready() const { return light_.id() != 0; }

  // Allocates what `frame`'s landing needs (the receivers' light at the G-buffer's
  // targetWidth x targetHeight) and frees the other's.
  Result reserve(const FrameDesc& frame, int targetWidth, int targetHeight, std::string& error);
  void release() {
    field_.release();
    receivers_.release();
  }
  // Attaches the view's target; GlError with a message when the framebuffer is incomplete.
  Result prepare(const FrameDesc& frame, std::string& error);
  // Records the field for the view's camera and adds its light into the view's target, under
  // CausticsPass::bindState's state (restored here for the seabed passes' viewport).
  // `inputs`: what the caustics pass's state bound (for the work account).
  void draw(const FrameDesc& frame, const ValidatedTextures& textures, const SeabedInputs& inputs);
  // Lets go of the host's texture.
  void finish();

  std::uint64_t allocatedBytes() const {
    return field_.allocatedBytes() + receivers_.allocatedBytes();
  }
  const ReflectedFieldPass& field() const { return field_; }
  const ReflectedReceiverPass& receivers() const { return receivers_; }

 private:
  ReflectedFieldPass field_;
  ReflectedReceiverPass receivers_;
  glkit::Program light_, lightOnDepth_;
  glkit::Framebuffer framebuffer_;
  glkit::Sampler sampler_;
};

// Whether any of the frame's view frustum can hold a receiver of the pass: the feature, the
// settings on, the sun above the horizon and some of the frustum above the water level.
bool reflectedCausticsHaveWork(const CreateDesc& create, const FrameDesc& frame);

}  // namespace postfx::detail
