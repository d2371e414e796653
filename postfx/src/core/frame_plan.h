#pragma once
// Which of a frame's passes run, decided once from the context's features and the frame's
// settings before any GL work: the memory estimate, the resources reserved, the passes recorded
// and the timers' skipped marks all read this one plan.
#include <array>

#include <postfx/diagnostics.h>
#include <postfx/postfx.h>

namespace postfx {
struct Context;
}

namespace postfx::detail {

struct FramePlan {
  bool caustics = false;  // the seabed caustics pass
  // The caustics model's pre-pass, for the caustics or the god rays (both read its field).
  bool wavefrontAreaRatio = false;
  bool tile = false;  // TileIrradiance
  // The local water regions' light (Feature::LocalWater, some region given), for the caustics
  // or the god rays.
  bool localWater = false;
  bool godRays = false;
  // The reflected caustics above the water (Feature::ReflectedCaustics): field and pass.
  bool reflected = false;
  bool objects = false;  // the sun's object caustics
  // The local lights whose object caustics run (indices into ObjectCausticsFrame::lights, in
  // order), and why each of the context's light slots does not.
  int lightCount = 0;
  std::array<int, kMaxLocalLightsLimit> lights{};
  std::array<LightSkip, kMaxLocalLightsLimit> lightSkip{};
  bool floor = false;  // benchmark mode (testing::BenchmarkFloor): every timed pass drained
  // The caustics pass's framebuffer and state are set up: a full-screen pass draws. The floor
  // runs whenever a timed pass does, so that every pass has its ratio.
  bool fullScreen = false;

  // Whether `pass` records GPU work this frame; one that does not is timed as skipped (0 ms).
  bool runs(Pass pass) const;
  // Whether the object caustics' maps are used at all: the sun's view or a light's.
  bool objectMaps() const { return objects || lightCount > 0; }
};

FramePlan planFrame(const Context& context, const FrameDesc& frame);

}  // namespace postfx::detail
