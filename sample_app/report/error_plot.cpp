#include "error_plot.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <cmath>
#include <cstdio>
#include <filesystem>

#include <atomic_file.h>

#include "gnuplot_plot.h"
#include "plot_layout.h"

namespace ocean::report {
namespace {

namespace algo = OIIO::ImageBufAlgo;

constexpr const char* kFont = "DejaVuSans";

const float kPalette[][3] = {{0.12f, 0.47f, 0.71f}, {1.00f, 0.50f, 0.05f}, {0.17f, 0.63f, 0.17f},
                             {0.84f, 0.15f, 0.16f}, {0.58f, 0.40f, 0.74f}, {0.55f, 0.34f, 0.29f},
                             {0.89f, 0.47f, 0.76f}, {0.50f, 0.50f, 0.50f}, {0.74f, 0.74f, 0.13f},
                             {0.09f, 0.75f, 0.81f}};

// The fallback when gnuplot is absent: the same layout drawn with OpenImageIO's lines and text.
class BuiltInDrawing {
 public:
  explicit BuiltInDrawing(const PlotLayout& layout)
      : image_(OIIO::ImageSpec(layout.width, layout.height, 3, OIIO::TypeDesc::FLOAT)),
        timeLabel_(layout.timeLabel) {
    const float white[3] = {1, 1, 1};
    algo::fill(image_, white);
    text(layout.width / 2, 24, layout.title, 18, algo::TextAlignX::Center);
    for (const PlotPanel& panel : layout.panels) drawPanel(panel);
  }
  OIIO::ImageBuf& image() { return image_; }

 private:
  void text(int x, int y, const std::string& s, int size, algo::TextAlignX ax,
            algo::TextAlignY ay = algo::TextAlignY::Center) {
    if (!labels_) return;
    const float black[3] = {0, 0, 0};
    labels_ = algo::render_text(image_, x, y, s, size, kFont, black, ax, ay);
    if (!labels_) (void)image_.geterror();  // no font: carry on unlabelled
  }

  void axes(const PlotPanel& panel) {
    const float black[3] = {0, 0, 0}, grid[3] = {0.87f, 0.87f, 0.87f};
    const int right = panel.left + panel.width, bottom = panel.top + panel.height;
    for (int d = panel.x0; d <= panel.x1; ++d) {
      for (int m = 1; m <= (d < panel.x1 ? 9 : 1); ++m) {
        const int x = panel.px(m * std::pow(10.0, d));
        algo::render_line(image_, x, panel.top, x, bottom, grid);
      }
      char label[32];
      std::snprintf(label, sizeof(label), "%g", std::pow(10.0, d));
      text(panel.px(std::pow(10.0, d)), bottom + 16, label, 13, algo::TextAlignX::Center);
    }
    for (int d = panel.y0; d <= panel.y1; ++d) {
      for (int m = 1; m <= (d < panel.y1 ? 9 : 1); ++m) {
        const int y = panel.py(m * std::pow(10.0, d));
        algo::render_line(image_, panel.left, y, right, y, grid);
      }
      char label[32];
      std::snprintf(label, sizeof(label), "%g", std::pow(10.0, d));
      text(panel.left - 6, panel.py(std::pow(10.0, d)), label, 13, algo::TextAlignX::Right);
    }
    algo::render_box(image_, panel.left, panel.top, right, bottom, black);
    text(panel.left + panel.width / 2, panel.top - 28, panel.title, 16, algo::TextAlignX::Center);
    // OIIO draws no rotated text: the error definition sits above the plot area.
    text(panel.left, panel.top - 10, "y: " + panel.errorAxis, 12, algo::TextAlignX::Left);
    text(panel.left + panel.width / 2, bottom + 40, timeLabel_, 13, algo::TextAlignX::Center);
  }

  void drawPanel(const PlotPanel& panel) {
    axes(panel);
    const float grey[3] = {0.25f, 0.25f, 0.25f};
    const std::vector<const PlotPoint*> front = panel.paretoFront();
    for (size_t i = 0; i < front.size(); ++i) {
      const int x = panel.px(front[i]->ms), y = panel.py(front[i]->error);
      for (int r : {kParetoRingPx - 1, kParetoRingPx})
        algo::render_box(image_, x - r, y - r, x + r, y + r, grey);
      if (i > 0) {  // a step: the best error reachable for this much time
        const int px = panel.px(front[i - 1]->ms), py = panel.py(front[i - 1]->error);
        for (int dash = px; dash < x; dash += 8)
          algo::render_line(image_, dash, py, std::min(dash + 4, x), py, grey);
        for (int dash = py; dash < y; dash += 8)
          algo::render_line(image_, x, dash, x, std::min(dash + 4, y), grey);
      }
    }
    for (size_t s = 0; s < panel.series.size(); ++s) {
      const float* colour = kPalette[s % std::size(kPalette)];
      const std::vector<PlotPoint>& points = panel.series[s].points;
      for (size_t i = 0; i < points.size(); ++i) {
        const int x = panel.px(points[i].ms), y = panel.py(points[i].error);
        if (i > 0)
          algo::render_line(image_, panel.px(points[i - 1].ms), panel.py(points[i - 1].error), x, y,
                            {colour, 3}, true);
        algo::render_box(image_, x - 3, y - 3, x + 3, y + 3, {colour, 3}, true);
        if (points[i].labelled)
          text(points[i].labelX, points[i].labelY, points[i].label, kLabelFontPx,
               algo::TextAlignX::Left, algo::TextAlignY::Bottom);
      }
      const int ly = panel.top + 10 + int(s) * 22;
      algo::render_box(image_, panel.legendX, ly - 5, panel.legendX + 12, ly + 5, {colour, 3},
                       true);
      text(panel.legendX + 20, ly, panel.series[s].method, 12, algo::TextAlignX::Left);
    }
    const int ly = panel.top + 10 + int(panel.series.size()) * 22;
    for (int r : {5, 6})
      algo::render_box(image_, panel.legendX + 6 - r, ly - r, panel.legendX + 6 + r, ly + r, grey);
    text(panel.legendX + 20, ly, "Pareto front", 12, algo::TextAlignX::Left);
  }

  OIIO::ImageBuf image_;
  bool labels_ = true;  // stays true while the font renders
  std::string timeLabel_;
};

}  // namespace

bool writeErrorPlot(const std::string& path, const std::string& title, const std::vector<Row>& rows,
                    std::string& error, PlotBackend backend, std::string* used, TimeAxis axis) {
  PlotLayout layout;
  if (!layoutErrorPlot(title, rows, layout, error, axis)) return false;
  OIIO::ImageBuf image;
  std::string drawnBy = "built-in";
  const std::string gnuplot = backend == PlotBackend::Auto ? findGnuplot() : "";
  if (!gnuplot.empty()) {
    const std::string script = std::filesystem::path(path).replace_extension(".gp").string();
    std::string why;
    if (drawWithGnuplot(gnuplot, layout, script, image, why)) {
      drawnBy = "gnuplot";
    } else {
      std::fprintf(stderr, "report: %s; drawing the plot without it\n", why.c_str());
    }
  }
  if (drawnBy != "gnuplot") image.copy(BuiltInDrawing(layout).image());
  if (used) *used = drawnBy;
  return writeThroughTemporary(
      path,
      [&](const std::string& temporary, std::string& why) {
        if (image.write(temporary, OIIO::TypeDesc::UINT8)) return true;
        why = "cannot write '" + path + "': " + image.geterror();
        return false;
      },
      error);
}

}  // namespace ocean::report
