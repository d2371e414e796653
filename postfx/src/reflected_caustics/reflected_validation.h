#pragma once
// Range checks of the reflected caustics' settings (postfx/reflected_caustics.h).
#include <string>

#include <postfx/postfx.h>

namespace postfx::detail {

Result validateReflectedCaustics(const ReflectedCausticsSettings& s, std::string& error);

}  // namespace postfx::detail
