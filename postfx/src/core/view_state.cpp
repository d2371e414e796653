#include "core/view_state.h"

namespace postfx::detail {

void initView(View& view, const std::array<bool, kPassCount>& present) {
  std::array<bool, kPassCount> own{};
  for (int p = 0; p < kPassCount; ++p) own[p] = present[p] && isViewPass(Pass(p));
  view.timers.init(own, 0);
}

}  // namespace postfx::detail
