#include "core/view_state.h"

#include <postfx/testing.h>

namespace postfx::detail {

void initView(View& view, const CreateDesc& desc, const std::array<bool, kPassCount>& present) {
  std::array<bool, kPassCount> own{};
  for (int p = 0; p < kPassCount; ++p) own[p] = present[p] && isViewPass(Pass(p));
  view.timers.init(own, 0);
  view.timers.initWork(desc.workAccount, hasFeature(desc.features, testing::CountShaderWork),
                       hasFeature(desc.features, testing::TimeEachStep));
}

}  // namespace postfx::detail
