#pragma once
// Validation of Feature::ObjectCaustics inputs: CPU values and GL *queries* only (no binds, no
// state changes), so a rejected frame leaves the host's GL state untouched.
#include <string>

#include <postfx/postfx.h>

namespace postfx::detail {

Result validateObjectCaustics(const FrameDesc& frame, std::string& error);

}  // namespace postfx::detail
