// Called without a current GL context (this binary never makes one), the plugin returns
// NoContext with a message; it never lets libepoxy abort the host.
#include <gtest/gtest.h>

#include <postfx/postfx.h>

TEST(PostfxWithoutContext, CreateRefusesInsteadOfAborting) {
  postfx::Context* fx = reinterpret_cast<postfx::Context*>(1);
  EXPECT_EQ(postfx::create(postfx::CreateDesc{}, fx), postfx::Result::NoContext);
  EXPECT_EQ(fx, nullptr);
  EXPECT_NE(std::string(postfx::lastError(nullptr)).find("context"), std::string::npos);
  EXPECT_STREQ(postfx::toString(postfx::Result::NoContext), "NoContext");
  postfx::destroy(nullptr);  // a no-op, with or without a context
}
