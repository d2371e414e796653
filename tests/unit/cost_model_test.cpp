// The cost model (docs/gpu_cost.md): the roofline's terms each scale with the work they are
// charged for, the largest one decides, the 2 x 2 quads' overshading follows the primitives'
// size, a view's per-pixel steps scale to another view's size and nothing else does, every GPU
// class figure carries its source, and Mesa's NIR dump is counted as the model reads it.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <gpu_cost.h>
#include <shader_statistics.h>

namespace {

using ocean::cost::GpuClass;

GpuClass rtx3060() {
  std::vector<GpuClass> classes;
  std::string error;
  EXPECT_TRUE(ocean::cost::selectGpuClasses("rtx3060", classes, error)) << error;
  return classes.empty() ? GpuClass{} : classes[0];
}

// A full-screen draw of `w` x `h` fragments writing RGBA16F, `fetches` per fragment.
postfx::WorkStep fullScreen(double w, double h, double fetches) {
  postfx::WorkStep s{};
  s.work.draws = 1;
  s.work.primitives = 1;
  s.work.vertices = 3;
  s.work.fragments = std::uint64_t(w * h);
  s.work.samplesPassed = s.work.fragments;
  s.work.fragmentFetches = std::uint64_t(w * h * fetches);
  s.work.fetches = s.work.fragmentFetches;
  s.work.bytesWritten = std::uint64_t(w * h * 8);
  s.targetBytes = 8;
  s.viewportPixels = std::uint64_t(w * h);
  return s;
}

TEST(GpuClasses, EveryClassTheBudgetNamesIsThereWithPositiveFigures) {
  std::vector<GpuClass> classes;
  std::string error;
  ASSERT_TRUE(ocean::cost::selectGpuClasses("gtx960m,rtx3060,rtx4090", classes, error)) << error;
  for (const GpuClass& c : classes) {
    SCOPED_TRACE(c.name);
    for (double figure : {c.clockHz, c.fp32Lanes, c.sfuLanes, c.tmus, c.rops, c.rasterEngines,
                          c.bandwidth, c.l2Bytes, c.atomicsPerClock, c.barrierSeconds})
      EXPECT_TRUE(figure > 0.0 && std::isfinite(figure));
  }
  // Sanity of the table against the vendors' throughput figures: the 3060's 199 GTexel/s and
  // 85.3 GPixel/s.
  const GpuClass& mid = classes[1];
  EXPECT_NEAR(mid.tmus * mid.clockHz / 1e9, 199.0, 1.0);
  EXPECT_NEAR(mid.rops * mid.clockHz / 1e9, 85.3, 0.5);
}

TEST(GpuClasses, AFigureWithoutItsSourceIsRefused) {
  const std::string figure = R"({"value": 1, "source": "x"})";
  auto table = [&](const std::string& clock) {
    return R"({"classes": [{"name": "g", "clock_mhz": )" + clock + R"(, "fp32_lanes": )" + figure +
           R"(, "sfu_lanes": )" + figure + R"(, "tmus": )" + figure + R"(, "rops": )" + figure +
           R"(, "raster_engines": )" + figure + R"(, "bandwidth_gbs": )" + figure +
           R"(, "l2_mb": )" + figure + R"(, "atomics_per_clock": )" + figure +
           R"(, "barrier_us": )" + figure + "}]}";
  };
  std::vector<GpuClass> out;
  std::string error;
  EXPECT_TRUE(ocean::cost::parseGpuClasses(table(figure), out, error)) << error;
  EXPECT_FALSE(ocean::cost::parseGpuClasses(table(R"({"value": 1})"), out, error));
  EXPECT_NE(error.find("clock_mhz"), std::string::npos) << error;
  EXPECT_FALSE(ocean::cost::parseGpuClasses(table(R"({"value": -1, "source": "x"})"), out, error));
  EXPECT_FALSE(ocean::cost::parseGpuClasses("not json", out, error));
  EXPECT_FALSE(ocean::cost::selectGpuClasses("rtx9999", out, error));
}

TEST(GpuCost, QuadsOvershadeSmallPrimitivesOnly) {
  EXPECT_DOUBLE_EQ(ocean::cost::fragmentLanes(1000.0, 1000.0), 4000.0);  // one pixel each
  EXPECT_DOUBLE_EQ(ocean::cost::fragmentLanes(1000.0, 4000.0), 4000.0);  // sub-pixel
  // A full-screen triangle's lanes are its fragments within a few per cent.
  EXPECT_NEAR(ocean::cost::fragmentLanes(2073600.0, 1.0) / 2073600.0, 1.0, 0.01);
  // 16-pixel primitives: (4 + 1)^2 / 16 lanes per fragment.
  EXPECT_DOUBLE_EQ(ocean::cost::fragmentLanes(1600.0, 100.0), 1600.0 * 25.0 / 16.0);
  EXPECT_EQ(ocean::cost::fragmentLanes(0.0, 10.0), 0.0);
}

TEST(GpuCost, EachTermIsItsWorkOverItsRateAndTheLargestDecides) {
  const GpuClass gpu = rtx3060();
  // Fetch-heavy: 64 fetches a pixel and no arithmetic stated: texture-bound at the TMU rate.
  postfx::WorkStep step = fullScreen(1920, 1080, 64);
  ocean::cost::StepEstimate e = ocean::cost::estimate(step, {}, gpu);
  EXPECT_STREQ(e.bound, "texture");
  // Each fetch once per lane: a full-screen triangle's quads shade a few edge lanes more.
  const double lanesPerFragment =
      ocean::cost::fragmentLanes(double(step.work.fragments), 1.0) / double(step.work.fragments);
  EXPECT_NEAR(e.texture, double(step.work.fetches) * lanesPerFragment / (gpu.tmus * gpu.clockHz),
              1e-12);
  EXPECT_NEAR(e.seconds, e.texture + gpu.barrierSeconds, 1e-12);
  // The same draw with 4000 instructions a fragment (RTX 3060: 32 lanes for each TMU, so over
  // 64 x 32 = 2048 it is the arithmetic): shading-bound, and twice the arithmetic twice the
  // shading term.
  ocean::cost::StepAlu alu;
  alu.fragment.ops = alu.fragment.gpuOps = 4000.0;
  e = ocean::cost::estimate(step, alu, gpu);
  EXPECT_STREQ(e.bound, "shading");
  alu.fragment.ops = alu.fragment.gpuOps = 8000.0;
  const ocean::cost::StepEstimate doubled = ocean::cost::estimate(step, alu, gpu);
  EXPECT_NEAR(doubled.shading / e.shading, 2.0, 0.01);
  // Bytes alone: memory-bound at the bandwidth.
  postfx::WorkStep copy{};
  copy.work.dispatches = 1;
  copy.work.bytesRead = 360u * 1000u * 1000u;
  e = ocean::cost::estimate(copy, {}, gpu);
  EXPECT_STREQ(e.bound, "memory");
  EXPECT_NEAR(e.memory, 1e-3, 1e-6);  // 360 MB at 360 GB/s
  // A million atomics: at the assumed per-channel rate.
  postfx::WorkStep scatter{};
  scatter.work.dispatches = 1;
  scatter.work.atomics = 1000000;
  e = ocean::cost::estimate(scatter, {}, gpu);
  EXPECT_STREQ(e.bound, "atomics");
  EXPECT_NEAR(e.atomics, 1e6 / (gpu.atomicsPerClock * gpu.clockHz), 1e-12);
  // Many sub-pixel triangles: the rasterisers' one triangle per clock each.
  postfx::WorkStep grid{};
  grid.work.draws = 1;
  grid.work.primitives = 8000000;
  grid.work.vertices = 4000000;
  e = ocean::cost::estimate(grid, {}, gpu);
  EXPECT_NEAR(e.raster, 8e6 / (gpu.rasterEngines * gpu.clockHz), 1e-12);
  // An RGBA32F target takes a ROP four clocks a sample, RGBA16F two.
  postfx::WorkStep wide = fullScreen(1920, 1080, 0);
  const double rop16 = ocean::cost::estimate(wide, {}, gpu).rop;
  wide.targetBytes = 16;
  EXPECT_NEAR(ocean::cost::estimate(wide, {}, gpu).rop / rop16, 2.0, 1e-9);
}

TEST(GpuCost, NoWorkCostsNothingButTheDispatch) {
  const GpuClass gpu = rtx3060();
  postfx::WorkStep empty{};
  EXPECT_EQ(ocean::cost::estimate(empty, {}, gpu).seconds, 0.0);
  empty.work.dispatches = 2;
  EXPECT_NEAR(ocean::cost::estimate(empty, {}, gpu).seconds, 2.0 * gpu.barrierSeconds, 1e-15);
}

TEST(GpuCost, AViewsPerPixelStepsScaleToAnotherViewAndNothingElseDoes) {
  const double from = 320.0 * 180.0, to = 1920.0 * 1080.0;
  const postfx::WorkStep full = fullScreen(320, 180, 3);
  const postfx::WorkStep big = ocean::cost::atViewSize(full, from, to);
  EXPECT_EQ(big.work.fragments, 1920u * 1080u);
  EXPECT_EQ(big.work.fetches, 3u * 1920u * 1080u);
  EXPECT_EQ(big.work.bytesWritten, 8u * 1920u * 1080u);
  EXPECT_EQ(big.work.primitives, 1u);
  // A quarter-resolution pass scales the same.
  const postfx::WorkStep quarter = fullScreen(80, 45, 16);
  EXPECT_EQ(ocean::cost::atViewSize(quarter, from, to).work.fragments, 480u * 270u);
  // A 256 x 256 pre-pass over the water's tiles, and a compute dispatch, are what they were.
  const postfx::WorkStep tiles = fullScreen(256, 256, 4);
  EXPECT_EQ(ocean::cost::atViewSize(tiles, from, to).work.fragments, tiles.work.fragments);
  postfx::WorkStep compute{};
  compute.work.dispatches = 1;
  compute.work.computeInvocations = 65536;
  EXPECT_EQ(ocean::cost::atViewSize(compute, from, to).work.computeInvocations, 65536u);
}

// The shape of Mesa 22's "NIR (final form)" dump, cut down to what the parser reads.
const char* kDump = R"(shader: MESA_SHADER_FRAGMENT
source_sha1: {0x0}
name: GLSL7
inputs: 0
impl main {
	block block_0:
	vec1 32 ssa_0 = load_const (0x3f800000 = 1.000000)
	vec4 32 ssa_1 = (float32)tex ssa_2 (coord), 0 (texture), 0 (sampler)
	vec1 32 ssa_3 = fmul ssa_1.x, ssa_0
	vec1 32 ssa_4 = fadd ssa_3, ssa_0
	vec1 32 ssa_5 = fneg ssa_4
	vec2 32 ssa_6 = fexp2 ssa_1.xy
	loop {
		block block_1:
		vec1 32 ssa_7 = frcp ssa_5
		vec4 32 ssa_8 = (float32)txl ssa_2 (coord), ssa_0 (lod), 1 (texture), 1 (sampler)
		vec3 32 ssa_9 = fmul ssa_8.xyz, ssa_7.xxx
		if ssa_10 {
			block block_2:
			vec1 32 ssa_11 = intrinsic ssbo_atomic_add (ssa_0, ssa_0, ssa_0) ()
		} else {
			block block_3:
		}
	}
	vec1 32 ssa_12 = vec2 ssa_0, ssa_0
}
shader: MESA_SHADER_COMPUTE
name: GLSL9
impl main {
	vec1 32 ssa_0 = iadd ssa_1, ssa_2
}
)";

TEST(ShaderStatistics, MesasDumpIsCountedInsideAndOutsideLoops) {
  const auto programs = ocean::cost::parseNirDump(kDump);
  ASSERT_EQ(programs.count(7), 1u);
  ASSERT_EQ(programs.count(9), 1u);
  const ocean::cost::StageStatistics& f = programs.at(7).fragment;
  EXPECT_TRUE(f.present);
  EXPECT_FALSE(programs.at(7).vertex.present);
  // fmul, fadd, fneg, fexp2 (2 components) outside; frcp and fmul (3) inside; constants,
  // textures, intrinsics and vector gathering are no arithmetic.
  EXPECT_DOUBLE_EQ(f.alu, 5.0);
  EXPECT_DOUBLE_EQ(f.loopAlu, 4.0);
  EXPECT_DOUBLE_EQ(f.transcendental, 2.0);
  EXPECT_DOUBLE_EQ(f.loopDivision, 1.0);
  EXPECT_DOUBLE_EQ(f.free, 2.0);  // the fneg, and the fadd of the fmul's product
  EXPECT_DOUBLE_EQ(f.tex, 1.0);
  EXPECT_DOUBLE_EQ(f.loopTex, 1.0);
  EXPECT_DOUBLE_EQ(f.loopAtomics, 1.0);
  // 9 fetches and 8 atomics counted per invocation: 1 fetch outside, so the loop ran 8 times
  // (its one fetch and one atomic each).
  EXPECT_DOUBLE_EQ(f.iterations(9.0, 8.0), 8.0);
  EXPECT_DOUBLE_EQ(f.perInvocation(9.0, 8.0), 5.0 + 4.0 * 8.0);
  EXPECT_DOUBLE_EQ(f.gpuPerInvocation(9.0, 8.0), 3.0 + 4.0 * 8.0);
  EXPECT_DOUBLE_EQ(programs.at(9).compute.alu, 1.0);
}

TEST(ShaderStatistics, TheTableRoundTripsAndRefusesMalformedText) {
  std::map<std::string, ocean::cost::ProgramStatistics> programs;
  programs["postfx.caustics"] = ocean::cost::parseNirDump(kDump).at(7);
  std::map<std::string, ocean::cost::ProgramStatistics> back;
  std::string error;
  ASSERT_TRUE(ocean::cost::readStatistics(ocean::cost::writeStatistics(programs), back, error))
      << error;
  ASSERT_EQ(back.count("postfx.caustics"), 1u);
  EXPECT_DOUBLE_EQ(back["postfx.caustics"].fragment.loopAlu, 4.0);
  EXPECT_FALSE(ocean::cost::readStatistics("{", back, error));
  EXPECT_FALSE(error.empty());
}

}  // namespace
