// Without a current GL context the ocean refuses with NoContext instead of letting libepoxy
// abort the host process (this binary never creates a context).
#include <gtest/gtest.h>

#include <glkit/current_context.h>
#include <postfx/water/ocean.h>

TEST(WaterWithoutContext, CreateRefusesInsteadOfAborting) {
  ASSERT_FALSE(glkit::hasCurrentContext());
  std::unique_ptr<water::Ocean> ocean;
  std::string error;
  EXPECT_EQ(water::Ocean::create(water::OceanDesc{}, ocean, error), water::Result::NoContext);
  EXPECT_EQ(ocean, nullptr);
  EXPECT_NE(error.find("context"), std::string::npos) << error;
}
