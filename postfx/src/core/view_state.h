#pragma once
// What one view (postfx/views.h) keeps between frames: the god-ray grid's pivot (it follows the
// view's camera), the view's own textures (raw output, reduced-resolution lookups and march) and
// the timers of its passes. A context's plain dispatch(context, frame) draws through a view of
// its own (Context::defaultView).
#include <cstdint>

#include <postfx/views.h>

#include "core/gpu_timers.h"
#include "god_rays/godrays_constants.h"
#include "god_rays/godrays_pass.h"
#include "seabed_caustics/caustics_pass.h"

namespace postfx {

struct View {
  detail::CausticsViewTextures caustics;
  detail::GodRaysViewTextures godRays;
  detail::GodRayGridPivot godRayPivot;
  detail::GpuTimers timers;  // Pass::WavefrontAreaRatio, Floor, Caustics, GodRays

  // The GPU memory the view holds now (its textures), from their sizes.
  std::uint64_t allocatedBytes() const {
    return caustics.allocatedBytes() + godRays.allocatedBytes();
  }
};

namespace detail {

// Whether `pass` runs once per view (timed in the view's timers) rather than once per frame
// (the context's).
constexpr bool isViewPass(Pass pass) {
  return pass == Pass::WavefrontAreaRatio || pass == Pass::Floor || pass == Pass::Caustics ||
         pass == Pass::GodRays || pass == Pass::ReflectedCaustics;
}

// Creates the view's timers (and work account) for the passes the context has (`present`,
// indexed by Pass).
void initView(View& view, const CreateDesc& desc, const std::array<bool, kPassCount>& present);

}  // namespace detail
}  // namespace postfx
