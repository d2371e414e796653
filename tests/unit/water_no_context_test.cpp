// Without a current GL context the ocean refuses with NoContext instead of letting libepoxy
// abort the host process (this binary never creates a context).
#include <gtest/gtest.h>

#include <glkit/current_context.h>
#include <postfx/water/ocean.h>

TEST(WaterWithoutContext, CreateRefusesInsteadOfAborting) {
  ASSERT_FALSE(glkit::hasCurrentContext());
  std::unique_ptr<postfx::water::Ocean> ocean;
  std::string error;
  EXPECT_EQ(postfx::water::Ocean::create(postfx::water::OceanDesc{}, ocean, error),
            postfx::water::Result::NoContext);
  EXPECT_EQ(ocean, nullptr);
  EXPECT_NE(error.find("context"), std::string::npos) << error;
}
