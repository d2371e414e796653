// ocean_sample bench --work on every preset's features: each step's counted fetches and atomics
// (testing::CountShaderWork) never exceed what its shaders state per invocation (their full
// path, or the bound of a data-dependent loop), and every estimate is labelled one and finite.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "sample_run.h"

namespace fs = std::filesystem;

namespace {

class SampleWorkBench : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("ocean_work_bench_" + std::to_string(getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

struct Case {
  const char* what;
  const char* arguments;
  std::vector<const char*> steps;  // steps the run must have recorded
};

const Case kCases[] = {
    {"shallow: tile field, god rays, glass and metal with their volume light",
     "--preset shallow --volume-caustics",
     {"tile_irradiance.scatter", "caustics.light", "god_rays.march", "object_caustics.trace",
      "object_caustics.splats", "object_caustics.composite", "volume_caustics.beams"}},
    {"torch: a spot light's object caustics",
     "--preset torch --volume-caustics",
     {"object_caustics.trace [light 0]", "volume_caustics.beams [light 0]"}},
    {"seabed: the wavefront area ratio's window",
     "--preset seabed --caustics-model wavefront-area-ratio --caustics-grid 64",
     {"wavefront_area_ratio.vertices", "wavefront_area_ratio.triangles",
      "wavefront_area_ratio.points", "wavefront_area_ratio.spread"}},
    {"harbour: reflected caustics on the view's depth",
     "--preset harbour --reflected-grid 128",
     {"reflected_caustics.rays", "reflected_caustics.landing_triangles",
      "reflected_caustics.light"}},
    {"harbour: reflected caustics on height layers",
     "--preset harbour --reflected-grid 128 --reflected-landing layers",
     {"reflected_caustics.vertices", "reflected_caustics.triangles", "reflected_caustics.light"}},
    {"pool: a local water region",
     "--preset pool --local-water-grid 64",
     {"local_water.vertices", "local_water.triangles", "local_water.points"}},
};

class SampleWorkBenchCase : public SampleWorkBench, public ::testing::WithParamInterface<int> {};

TEST_P(SampleWorkBenchCase, CountedWorkStaysWithinWhatEveryShaderStates) {
  {
    const Case& c = kCases[GetParam()];
    SCOPED_TRACE(c.what);
    const fs::path json = dir_ / "work.json";
    const testsupport::SampleRun run = testsupport::runSample(
        OCEAN_SAMPLE_EXE,
        std::string("bench --work --gpu all --width 160 --height 90 --frames 1 ") + c.arguments +
            " --json " + json.string(),
        dir_);
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.out.find("ESTIMATE"), std::string::npos) << "an estimate says so";
    // The driver's dump of every program goes to the cost model, never to the user's terminal.
    EXPECT_EQ(run.err.find("MESA_SHADER"), std::string::npos);
    EXPECT_EQ(run.out.find("MESA_SHADER"), std::string::npos);
    std::ifstream in(json);
    const nlohmann::json report = nlohmann::json::parse(in, nullptr, false);
    ASSERT_FALSE(report.is_discarded());
    EXPECT_NE(report["estimate"].get<std::string>().find("not a measurement"), std::string::npos);
    for (const char* name : c.steps) {
      bool found = false;
      for (const auto& step : report["steps"]) found = found || step["name"] == name;
      EXPECT_TRUE(found) << name;
    }
    for (const auto& step : report["steps"]) {
      const std::string name = step["name"];
      SCOPED_TRACE(name);
      const double fetches = step["fetches"], stated = step["stated_fetches"];
      const double atomics = step["atomics"], statedAtomics = step["stated_atomics"];
      // Rounding of a per-invocation share (a dispatch's padding) moves a stated count by 1.
      EXPECT_LE(fetches, stated + 1.0);
      EXPECT_LE(atomics, statedAtomics + 1.0);
      // Every shaded step has its program's arithmetic (Mesa's NIR reached the model).
      if (step["fragments"].get<double>() > 0.0)
        EXPECT_GT(step["alu_per_invocation"]["fragment"].get<double>(), 0.0);
      if (step["compute_invocations"].get<double>() > 0.0)
        EXPECT_GT(step["alu_per_invocation"]["compute"].get<double>(), 0.0);
      for (const auto& [gpu, e] : step["estimate"].items()) {
        const double ms = e["ms"];
        EXPECT_TRUE(std::isfinite(ms) && ms >= 0.0) << gpu;
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Features, SampleWorkBenchCase,
                         ::testing::Range(0, int(sizeof(kCases) / sizeof(kCases[0]))));

TEST_F(SampleWorkBench, AnUnknownGpuClassIsRefusedNamingTheKnownOnes) {
  const testsupport::SampleRun run = testsupport::runSample(
      OCEAN_SAMPLE_EXE, "bench --work --gpu rtx9999 --width 64 --height 36", dir_);
  EXPECT_NE(run.exitCode, 0);
  EXPECT_NE(run.err.find("rtx9999"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("rtx3060"), std::string::npos) << run.err;
}

}  // namespace
