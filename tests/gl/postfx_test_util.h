#pragma once
// Small helpers shared by the postfx GL tests.
#include <gtest/gtest.h>

#include <memory>

#include <postfx/postfx.h>
#include <postfx/testing.h>

namespace postfxtest {

struct ContextDeleter {
  void operator()(postfx::Context* c) const { postfx::destroy(c); }
};
using ContextPtr = std::unique_ptr<postfx::Context, ContextDeleter>;

inline ContextPtr makeContext(postfx::Feature features, int depthConvention = 0,
                              int normalEncoding = 0) {
  postfx::CreateDesc desc;
  desc.features = features;
  desc.depthConvention = static_cast<postfx::DepthConvention>(depthConvention);
  desc.normalEncoding = static_cast<postfx::NormalEncoding>(normalEncoding);
  postfx::Context* fx = nullptr;
  const postfx::Result r = postfx::create(desc, fx);
  EXPECT_EQ(r, postfx::Result::Ok) << postfx::lastError(nullptr);
  return ContextPtr(fx);
}

inline constexpr postfx::Feature kRaw =
    postfx::Feature::Caustics | postfx::testing::RawCausticOutput;

}  // namespace postfxtest
