#pragma once
// One frame from its description to recorded GL work: validation, the plan, the constants, the
// memory check, the programs and resources it needs, then the planned passes in order. A
// refusal at any step leaves the host's target and the context as they were.
#include <span>

#include <postfx/postfx.h>

namespace postfx::detail {

// dispatch's work once a GL context is known current; throws only std::bad_alloc. `views`: the
// host's list (`listed`: validated as a list, its messages name views[i]) or the context's own
// view for a plain dispatch(context, frame).
Result dispatchFrame(Context& context, const FrameDesc& frame, std::span<const ViewDesc> views,
                     bool listed);

}  // namespace postfx::detail
