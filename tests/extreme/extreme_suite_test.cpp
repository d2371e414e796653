// The extreme-case suite: every row of extreme_table.cpp on every pass it names, one gtest case
// (and one ctest entry) each. A case asserts that the pass accepts the inputs, that no output
// value is NaN/Inf, that the outputs stay inside the model's physical bounds, and, where the row
// names a sweep, that a 1e-4 step of that parameter moves the output by no more than the bound
// derived in extreme_bounds.cpp. The binary ends with one line: how many cases ran and failed.
#include <gtest/gtest.h>

#include <cstdio>

#include "extreme_bounds.h"
#include "extreme_case.h"
#include "extreme_runner.h"
#include "gl_fixture.h"

namespace {

using extreme::Case;

class ExtremeCaseTest : public testsupport::GlTest, public ::testing::WithParamInterface<Case> {};

TEST_P(ExtremeCaseTest, FiniteBoundedContinuous) {
  const Case& c = GetParam();
  extreme::Knobs knobs = c.knobs();
  const extreme::Sweep sweep = c.row->sweep;
  if (extreme::continuityNeedsUniformSampling(c.pass, sweep)) knobs.uniformSampling = true;
  extreme::Runner runner(c.pass);
  const extreme::Output base = runner.run(knobs);
  ASSERT_TRUE(base.error.empty()) << base.error;
  ASSERT_FALSE(base.light.empty());

  const size_t nonFinite = extreme::nonFiniteCount(base);
  const extreme::Excess excess = extreme::boundExcess(base, c.pass);
  double peak = 0.0;
  for (const glm::vec4& p : base.light) peak = std::max({peak, double(p.r), double(p.g)});
  std::printf("%s: %zu non-finite, worst bound excess %.3g (of full scale), peak output %.4g%s%s\n",
              c.name.c_str(), nonFinite, excess.worst, peak, base.note.empty() ? "" : "; ",
              base.note.c_str());
  EXPECT_EQ(nonFinite, 0u) << "NaN/Inf in the outputs";
  EXPECT_LE(excess.worst, 0.0) << excess.where;

  if (sweep == extreme::Sweep::None) return;
  const extreme::Output moved = runner.run(extreme::stepped(knobs, sweep));
  ASSERT_TRUE(moved.error.empty()) << moved.error;
  EXPECT_EQ(extreme::nonFiniteCount(moved), 0u);
  const extreme::Continuity cont = extreme::continuity(c.pass, sweep, knobs, base, moved);
  std::printf("%s: step 1e-4 in %s%s: mean |change| %.3g of full scale, derived limit %.3g (%s)\n",
              c.name.c_str(), extreme::sweepName(sweep),
              knobs.uniformSampling ? " (samples evenly along the ray)" : "", cont.change,
              cont.limit, cont.derivation.c_str());
  RecordProperty("continuity_change", std::to_string(cont.change));
  RecordProperty("continuity_limit", std::to_string(cont.limit));
  EXPECT_LE(cont.change, cont.limit);
}

INSTANTIATE_TEST_SUITE_P(Extreme, ExtremeCaseTest, ::testing::ValuesIn(extreme::cases()),
                         [](const ::testing::TestParamInfo<Case>& param) {
                           return param.param.name;
                         });

// The summary line: cases of this suite that ran in this process and how many failed.
class SummaryEnvironment : public ::testing::Environment {
 public:
  void TearDown() override {
    const ::testing::UnitTest& unit = *::testing::UnitTest::GetInstance();
    int ran = 0, failed = 0;
    for (int s = 0; s < unit.total_test_suite_count(); ++s) {
      const ::testing::TestSuite& suite = *unit.GetTestSuite(s);
      for (int t = 0; t < suite.total_test_count(); ++t) {
        const ::testing::TestInfo& info = *suite.GetTestInfo(t);
        if (!info.should_run()) continue;
        ++ran;
        if (info.result()->Failed()) ++failed;
      }
    }
    std::printf("extreme-case suite: %d cases ran, %d failed (table: %zu cases)\n", ran, failed,
                extreme::cases().size());
  }
};

const ::testing::Environment* const kSummary =
    ::testing::AddGlobalTestEnvironment(new SummaryEnvironment);

}  // namespace
