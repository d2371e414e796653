// The pool preset (local water: its ripple simulation as a Replace region) against its traced
// reference at 640x360, the pattern alone (each added light divided by flat water's): the
// plugin's region light agrees with photons traced through the same simulation texture.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <regex>
#include <string>

#include <sample_run.h>

namespace {

namespace fs = std::filesystem;

testsupport::SampleRun sample(const std::string& arguments, const fs::path& scratch) {
  return testsupport::runSample(OCEAN_SAMPLE_EXE, arguments, scratch);
}

TEST(SamplePoolReference, PatternAgreesWithTracedLightAt640x360) {
  const fs::path dir = fs::temp_directory_path() / ("pool_reference_" + std::to_string(getpid()));
  fs::create_directories(dir);
  // No god rays: flat water's frame would light its shafts otherwise (compare --help).
  const std::string scene = "--preset pool --width 640 --height 360 --no-god-rays ";
  const std::string p = (dir / "P.exr").string(), b = (dir / "B.exr").string(),
                    f = (dir / "F.exr").string(), r = (dir / "R.exr").string();
  for (const std::string& arguments :
       {"render " + scene + "--out " + p,
        "render " + scene + "--no-caustics --no-object-caustics --out " + b,
        "render " + scene +
            "--caustics-model ray-deviation --tau 0 --no-object-caustics --flat-local-water "
            "--out " +
            f,
        "reference " + scene + "--out " + r}) {
    const testsupport::SampleRun run = sample(arguments, dir);
    ASSERT_EQ(run.exitCode, 0) << arguments << "\n" << run.err;
  }
  const testsupport::SampleRun compare =
      sample("compare --plugin " + p + " --reference " + r + " --base " + b + " --flat " + f +
                 " --out " + (dir / "compare.png").string(),
             dir);
  ASSERT_EQ(compare.exitCode, 0) << compare.err;
  const std::string all = compare.out + compare.err;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(
      all, m,
      std::regex(
          R"(pattern[^\n]*correlation ([0-9.]+), relative RMSE ([0-9.]+); contrast \(std/mean\) plugin ([0-9.]+), reference ([0-9.]+))")))
      << all;
  const double correlation = std::stod(m[1]), rmse = std::stod(m[2]);
  const double contrast = std::stod(m[3]), referenceContrast = std::stod(m[4]);
  std::printf(
      "pool at 640x360, pattern: correlation %.4f, relative RMSE %.4f, contrast %.3f vs %.3f\n",
      correlation, rmse, contrast, referenceContrast);
  EXPECT_GE(correlation, 0.9);
  EXPECT_LE(rmse, 0.25);
  EXPECT_NEAR(contrast / referenceContrast, 1.0, 0.15);
  fs::remove_all(dir);
}

}  // namespace
