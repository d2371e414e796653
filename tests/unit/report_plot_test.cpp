// The report's plot: one panel per effect with one error definition each,
// the Pareto front, labels that collide with nothing, and a PNG from either drawing.
#include <gtest/gtest.h>

#include <OpenImageIO/imagebuf.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>

#include <error_plot.h>
#include <gnuplot_plot.h>
#include <plot_layout.h>
#include <report_table.h>
#include <source_revision.h>

namespace {

namespace fs = std::filesystem;
using ocean::report::Row;

Row row(const std::string& pass, const std::string& method, const std::string& setting, double ms,
        double relative, double affine) {
  Row r;
  r.pass = pass;
  r.method = method;
  r.setting = setting;
  r.medianMs = ms;
  r.relativeRmse = relative;
  r.affineRmse = affine;
  return r;
}

std::vector<Row> reportLikeRows() {
  return {
      row("god_rays", "god rays, world grid", "8 samples", 0.5, 0.20, 0.1),
      row("god_rays", "god rays, world grid", "16 samples", 1.0, 0.10, 0.05),
      row("god_rays", "god rays, half res", "16 samples", 0.4, 0.15, 0.05),
      row("caustics", "ray deviation", "tau 800", 0.8, ocean::report::kNotApplicable, 0.6),
      row("caustics", "wavefront area ratio", "grid 256", 2.0, 0.9, 0.3),
      row("caustics", "ray deviation on a slope, along the light", "slope 30, facing the sun", 0.8,
          ocean::report::kNotApplicable, 0.7),
      row("object_caustics", "caustic map", "512 / 256 / 1", 3.0, 0.05, 0.01),
      row("new_pass", "something new", "1", 1.0, 0.2, 0.2),
      row("god_rays", "untimed", "1", 0.0, 0.2, 0.2),  // no time: not plotted
  };
}

TEST(ReportPlot, OnePanelPerEffectWithOneErrorDefinition) {
  ocean::report::PlotLayout layout;
  std::string error;
  ASSERT_TRUE(ocean::report::layoutErrorPlot("t", reportLikeRows(), layout, error)) << error;
  ASSERT_EQ(layout.panels.size(), 5u);
  EXPECT_EQ(layout.panels[0].title, "seabed caustics (flat seabed)");
  EXPECT_EQ(layout.panels[1].title, "seabed caustics on slopes");
  EXPECT_EQ(layout.panels[2].title, "god rays");
  EXPECT_EQ(layout.panels[3].title, "object caustics");
  EXPECT_EQ(layout.panels[4].title, "new_pass") << "a pass no panel names gets its own";
  // Seabed models are all compared after their affine fit (the ray-deviation factor has no
  // scale), the physical model included; god rays on the absolute relative RMSE.
  ASSERT_EQ(layout.panels[0].series.size(), 2u);
  EXPECT_DOUBLE_EQ(layout.panels[0].series[1].points[0].error, 0.3);
  EXPECT_NE(layout.panels[0].errorAxis.find("a x + b"), std::string::npos);
  EXPECT_NE(layout.panels[2].errorAxis.find("dense march"), std::string::npos);
  size_t godRayPoints = 0;
  for (const auto& series : layout.panels[2].series) godRayPoints += series.points.size();
  EXPECT_EQ(godRayPoints, 3u) << "the untimed row is left out";
  EXPECT_EQ(layout.panels[2].series[0].points[1].label, "16");
  // Every panel fits on the canvas, legend included.
  for (const auto& panel : layout.panels) {
    EXPECT_GE(panel.left, 0);
    EXPECT_LE(panel.legendX + 300, layout.width) << panel.title;
    EXPECT_LE(panel.top + panel.height, layout.height);
  }
}

// The flat seabed is measured at 320x180, 640x360 and 1280x720: the panel plots the largest
// size's pattern error only, and the smaller sizes (in the table) get no panel of their own.
TEST(ReportPlot, FlatSeabedPanelPlotsTheLargestSize) {
  std::vector<Row> rows;
  for (const int width : {320, 1280, 640}) {
    Row r = row("caustics", "tile irradiance", "tiles 128", 1.0 + width / 320.0, 0.2,
                0.1 + width / 1.0e4);
    r.width = width;
    r.height = width * 9 / 16;
    rows.push_back(r);
  }
  rows.push_back(row("caustics", "ray deviation on a slope, along the light", "slope 30", 0.8,
                     ocean::report::kNotApplicable, 0.7));
  ocean::report::PlotLayout layout;
  std::string error;
  ASSERT_TRUE(ocean::report::layoutErrorPlot("t", rows, layout, error)) << error;
  ASSERT_EQ(layout.panels.size(), 2u) << "no panel for the smaller sizes";
  EXPECT_EQ(layout.panels[0].title, "seabed caustics (flat seabed, 1280x720)");
  ASSERT_EQ(layout.panels[0].series.size(), 1u);
  ASSERT_EQ(layout.panels[0].series[0].points.size(), 1u);
  EXPECT_DOUBLE_EQ(layout.panels[0].series[0].points[0].error, 0.1 + 1280 / 1.0e4);
  EXPECT_EQ(layout.panels[1].title, "seabed caustics on slopes");
}

TEST(ReportPlot, ParetoFrontIsThePointsNothingBeats) {
  std::vector<Row> rows = {
      row("god_rays", "a", "1", 1.0, 0.5, 0), row("god_rays", "a", "2", 2.0, 0.3, 0),
      row("god_rays", "b", "3", 3.0, 0.4, 0), row("god_rays", "b", "4", 4.0, 0.1, 0),
      row("god_rays", "b", "5", 0.5, 0.9, 0)};
  ocean::report::PlotLayout layout;
  std::string error;
  ASSERT_TRUE(ocean::report::layoutErrorPlot("t", rows, layout, error)) << error;
  std::vector<double> front;
  for (const auto* p : layout.panels[0].paretoFront()) front.push_back(p->ms);
  EXPECT_EQ(front, (std::vector<double>{0.5, 1.0, 2.0, 4.0})) << "3 ms is beaten by 2 ms";
}

// Forty points crowded into a corner of one decade: every label placed collides with no other
// label and no point and stays inside the plot area; the rest are left out (the report's table
// has every setting), but not all of them.
TEST(ReportPlot, LabelsDoNotCollide) {
  std::vector<Row> rows;
  for (int i = 0; i < 40; ++i)
    rows.push_back(row("god_rays", std::string(1, char('a' + i % 4)),
                       std::to_string(100 + i) + " samples", 1.0 + 0.02 * i, 0.1 + 0.001 * (i % 7),
                       0));
  ocean::report::PlotLayout layout;
  std::string error;
  ASSERT_TRUE(ocean::report::layoutErrorPlot("t", rows, layout, error)) << error;
  const auto& panel = layout.panels[0];
  struct Box {
    int x0, y0, x1, y1;
  };
  std::vector<Box> labels, points;
  for (const auto& s : panel.series)
    for (const auto& p : s.points) {
      // The marker, or the ring round a Pareto point, which labels must not cover either.
      const int r = p.pareto ? ocean::report::kParetoRingPx : 4;
      points.push_back(
          {panel.px(p.ms) - r, panel.py(p.error) - r, panel.px(p.ms) + r, panel.py(p.error) + r});
      if (p.labelled)
        labels.push_back({p.labelX, p.labelY - ocean::report::kLabelFontPx,
                          p.labelX + ocean::report::kLabelCharPx * int(p.label.size()), p.labelY});
    }
  auto overlap = [](const Box& a, const Box& b) {
    return a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1;
  };
  EXPECT_GE(labels.size(), 4u);
  for (size_t i = 0; i < labels.size(); ++i) {
    EXPECT_GE(labels[i].x0, panel.left);
    EXPECT_LE(labels[i].x1, panel.left + panel.width);
    for (size_t j = i + 1; j < labels.size(); ++j) EXPECT_FALSE(overlap(labels[i], labels[j]));
    for (const Box& p : points) EXPECT_FALSE(overlap(labels[i], p));
  }
}

class ReportPlotFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("ocean_plot_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override {
    if (const char* keep = std::getenv("OCEAN_KEEP_PLOT"))  // to look at the drawing
      fs::copy_file(dir_ / "error_vs_time.png", keep, fs::copy_options::overwrite_existing);
    fs::remove_all(dir_);
  }

  void expectPlot(ocean::report::PlotBackend backend, const std::string& expectedBy) {
    const fs::path png = dir_ / "error_vs_time.png";
    std::string error, used;
    ASSERT_TRUE(ocean::report::writeErrorPlot(png.string(), "title", reportLikeRows(), error,
                                              backend, &used))
        << error;
    EXPECT_EQ(used, expectedBy);
    ocean::report::PlotLayout layout;
    ASSERT_TRUE(ocean::report::layoutErrorPlot("title", reportLikeRows(), layout, error));
    OIIO::ImageBuf image(png.string());
    ASSERT_TRUE(image.read()) << image.geterror();
    EXPECT_EQ(image.spec().width, layout.width);
    EXPECT_EQ(image.spec().height, layout.height);
    for (const auto& entry : fs::directory_iterator(dir_))
      EXPECT_EQ(entry.path().filename().string().find("partial"), std::string::npos)
          << entry.path();
  }
  fs::path dir_;
};

TEST_F(ReportPlotFile, BuiltInDrawingWritesThePng) {
  expectPlot(ocean::report::PlotBackend::BuiltIn, "built-in");
}

// The table names each row's size (the report's timed size where a row has none) and the
// pattern contrast of both sides where the row has one.
TEST_F(ReportPlotFile, TableNamesEachRowsSizeAndContrast) {
  std::vector<Row> rows = {row("god_rays", "god rays", "16 samples", 1.0, 0.2, 0.1),
                           row("caustics", "tile irradiance", "tiles 128", 2.0, 0.25, 0.2)};
  rows[1].width = 1280;
  rows[1].height = 720;
  rows[1].contrast = 0.48;
  rows[1].referenceContrast = 0.55;
  ocean::report::ReportInfo info;
  info.width = 320;
  info.height = 180;
  std::string error;
  const fs::path csv = dir_ / "t.csv", md = dir_ / "t.md";
  ASSERT_TRUE(ocean::report::writeCsv(csv.string(), info, rows, error)) << error;
  ASSERT_TRUE(ocean::report::writeMarkdown(md.string(), info, rows, "", error)) << error;
  auto read = [](const fs::path& path) {
    std::ifstream in(path);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  const std::string csvText = read(csv), mdText = read(md);
  EXPECT_NE(csvText.find("god rays,16 samples,320x180,"), std::string::npos) << csvText;
  EXPECT_NE(csvText.find("tiles 128,1280x720,"), std::string::npos) << csvText;
  EXPECT_NE(csvText.find(",0.48,0.55,"), std::string::npos) << csvText;
  EXPECT_NE(mdText.find("| 1280x720 |"), std::string::npos) << mdText;
  EXPECT_NE(mdText.find("| 0.480 / 0.550 |"), std::string::npos) << mdText;
}

// The estimate's axis plots each row at its estimated GPU time, leaves out the rows never
// estimated, and says it is an estimate; the table carries the estimate beside the measurement
// and links the second plot.
TEST_F(ReportPlotFile, EstimatedGpuTimeHasItsOwnAxisAndColumn) {
  std::vector<Row> rows = {row("god_rays", "god rays", "8 samples", 40.0, 0.2, 0.1),
                           row("god_rays", "god rays", "16 samples", 80.0, 0.1, 0.05),
                           row("god_rays", "god rays", "32 samples", 160.0, 0.05, 0.02)};
  rows[0].estimatedMs = 0.06;
  rows[1].estimatedMs = 0.11;  // the 32-sample row was not estimated
  ocean::report::PlotLayout measured, estimated;
  std::string error;
  ASSERT_TRUE(ocean::report::layoutErrorPlot("t", rows, measured, error)) << error;
  ASSERT_TRUE(ocean::report::layoutErrorPlot("t", rows, estimated, error,
                                             ocean::report::TimeAxis::Estimated))
      << error;
  ASSERT_EQ(estimated.panels.size(), 1u);
  ASSERT_EQ(estimated.panels[0].series[0].points.size(), 2u);
  EXPECT_DOUBLE_EQ(estimated.panels[0].series[0].points[1].ms, 0.11);
  EXPECT_EQ(measured.panels[0].series[0].points.size(), 3u);
  EXPECT_NE(estimated.timeLabel.find("ESTIMATED"), std::string::npos);
  EXPECT_EQ(measured.timeLabel.find("ESTIMATED"), std::string::npos);
  EXPECT_TRUE(ocean::report::anyEstimated(rows));
  EXPECT_FALSE(ocean::report::anyEstimated({row("god_rays", "g", "1", 1.0, 0.1, 0.1)}));
  EXPECT_EQ(ocean::report::estimatePlotFile("error_vs_time.png"), "error_vs_time_gpu_estimate.png");
  EXPECT_EQ(ocean::report::estimatePlotFile("out.d/plot"), "out.d/plot_gpu_estimate");

  ocean::report::ReportInfo info;
  info.width = 320;
  info.height = 180;
  const fs::path csv = dir_ / "t.csv", md = dir_ / "t.md";
  ASSERT_TRUE(ocean::report::writeCsv(csv.string(), info, rows, error)) << error;
  ASSERT_TRUE(ocean::report::writeMarkdown(md.string(), info, rows, "p.png", error)) << error;
  auto read = [](const fs::path& path) {
    std::ifstream in(path);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  const std::string csvText = read(csv), mdText = read(md);
  EXPECT_NE(csvText.find("floor_ratio,estimated_gpu_ms,"), std::string::npos) << csvText;
  EXPECT_NE(csvText.find(",0.11,"), std::string::npos) << csvText;
  EXPECT_NE(mdText.find("est. GPU ms"), std::string::npos) << mdText;
  EXPECT_NE(mdText.find("| 0.110 |"), std::string::npos) << mdText;
  EXPECT_NE(mdText.find("(p_gpu_estimate.png)"), std::string::npos) << mdText;
  EXPECT_NE(mdText.find("not a measurement"), std::string::npos) << mdText;
  // The built-in drawing writes the estimate's plot too.
  const fs::path png = dir_ / "error_vs_time.png";
  ASSERT_TRUE(ocean::report::writeErrorPlot(png.string(), "t", rows, error,
                                            ocean::report::PlotBackend::BuiltIn, nullptr,
                                            ocean::report::TimeAxis::Estimated))
      << error;
  OIIO::ImageBuf image(png.string());
  EXPECT_TRUE(image.read()) << image.geterror();
}

// The table says when and from which code it was measured, so docs/measurements.md can quote it;
// a run that knows neither says so rather than leaving the line out.
TEST_F(ReportPlotFile, TableNamesItsDateAndCodeRevision) {
  const std::vector<Row> rows = {row("god_rays", "god rays", "16 samples", 1.0, 0.2, 0.1)};
  ocean::report::ReportInfo info;
  info.width = 320;
  info.height = 180;
  info.date = "2026-12-05";
  info.revision = "9ef65c6-dirty";
  std::string error;
  const fs::path md = dir_ / "t.md";
  auto read = [](const fs::path& path) {
    std::ifstream in(path);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  ASSERT_TRUE(ocean::report::writeMarkdown(md.string(), info, rows, "", error)) << error;
  const std::string named = read(md);
  EXPECT_NE(named.find("\nMeasured 2026-12-05 (UTC) from code revision `9ef65c6-dirty`.\n"),
            std::string::npos)
      << named;
  info.date.clear();
  info.revision.clear();
  ASSERT_TRUE(ocean::report::writeMarkdown(md.string(), info, rows, "", error)) << error;
  const std::string unnamed = read(md);
  EXPECT_NE(unnamed.find("Measured on an unknown date from code revision `unknown`."),
            std::string::npos)
      << unnamed;
  // The build's own revision: one line, no quote that would break the markdown.
  const std::string revision = ocean::report::sourceRevision();
  EXPECT_FALSE(revision.empty());
  EXPECT_EQ(revision.find_first_of("\n`\""), std::string::npos) << revision;
  EXPECT_EQ(ocean::report::utcDate().size(), 10u);
}

TEST_F(ReportPlotFile, GnuplotDrawsWhenInstalled) {
  if (ocean::report::findGnuplot().empty()) GTEST_SKIP() << "no gnuplot on PATH (gnuplot-nox)";
  expectPlot(ocean::report::PlotBackend::Auto, "gnuplot");
  EXPECT_TRUE(fs::exists(dir_ / "error_vs_time.gp")) << "the script is kept beside the plot";
}

}  // namespace
