#pragma once
// One frame from its description to recorded GL work: validation, the plan, the constants, the
// memory check, the programs and resources it needs, then the planned passes in order. A
// refusal at any step leaves the host's target and the context as they were.
#include <postfx/postfx.h>

namespace postfx::detail {

// dispatch's work once a GL context is known current; throws only std::bad_alloc.
Result dispatchFrame(Context& context, const FrameDesc& frame);

}  // namespace postfx::detail
