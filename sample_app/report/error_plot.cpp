#include "error_plot.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include <atomic_file.h>

namespace ocean::report {
namespace {

namespace algo = OIIO::ImageBufAlgo;

constexpr int kWidth = 1000, kHeight = 640;
constexpr int kLeft = 90, kRight = 330, kTop = 76, kBottom = 70;  // margins; legend on the right
constexpr const char* kFont = "DejaVuSans";

struct Point {
  double ms, error;
  std::string setting;
};

// Decade range [lo, hi] covering every value, at least one decade wide.
void decades(const std::vector<double>& values, int& lo, int& hi) {
  double mn = HUGE_VAL, mx = 0.0;
  for (double v : values) mn = std::min(mn, v), mx = std::max(mx, v);
  lo = int(std::floor(std::log10(mn)));
  hi = int(std::ceil(std::log10(mx)));
  if (hi <= lo) hi = lo + 1;
}

const float kPalette[][3] = {{0.12f, 0.47f, 0.71f}, {1.00f, 0.50f, 0.05f}, {0.17f, 0.63f, 0.17f},
                             {0.84f, 0.15f, 0.16f}, {0.58f, 0.40f, 0.74f}, {0.55f, 0.34f, 0.29f},
                             {0.89f, 0.47f, 0.76f}, {0.50f, 0.50f, 0.50f}, {0.74f, 0.74f, 0.13f},
                             {0.09f, 0.75f, 0.81f}, {0.00f, 0.00f, 0.00f}, {0.10f, 0.10f, 0.55f},
                             {0.80f, 0.00f, 0.80f}, {0.33f, 0.42f, 0.18f}};

}  // namespace

bool writeErrorPlot(const std::string& path, const std::string& title, const std::vector<Row>& rows,
                    std::string& error) {
  std::vector<std::string> order;  // methods in first-appearance order
  std::map<std::string, std::vector<Point>> series;
  std::vector<double> times, errors;
  for (const Row& row : rows) {
    const double e = row.plottedError();
    if (!(row.medianMs > 0.0) || !(e > 0.0) || !std::isfinite(e)) continue;
    if (!series.count(row.method)) order.push_back(row.method);
    series[row.method].push_back({row.medianMs, e, row.setting});
    times.push_back(row.medianMs);
    errors.push_back(e);
  }
  if (times.empty()) {
    error = "nothing to plot: no row has both a time and an error";
    return false;
  }
  int x0, x1, y0, y1;
  decades(times, x0, x1);
  decades(errors, y0, y1);
  const int plotW = kWidth - kLeft - kRight, plotH = kHeight - kTop - kBottom;
  auto px = [&](double ms) {
    return kLeft + int(std::lround((std::log10(ms) - x0) / (x1 - x0) * plotW));
  };
  auto py = [&](double e) {
    return kTop + plotH - int(std::lround((std::log10(e) - y0) / (y1 - y0) * plotH));
  };

  OIIO::ImageBuf image(OIIO::ImageSpec(kWidth, kHeight, 3, OIIO::TypeDesc::FLOAT));
  const float white[3] = {1, 1, 1}, black[3] = {0, 0, 0}, grid[3] = {0.85f, 0.85f, 0.85f};
  algo::fill(image, white);
  bool labels = true;  // stays true while the font renders
  auto text = [&](int x, int y, const std::string& s, int size, algo::TextAlignX ax,
                  algo::TextAlignY ay) {
    if (!labels) return;
    labels = algo::render_text(image, x, y, s, size, kFont, black, ax, ay);
    if (!labels) (void)image.geterror();  // no font: carry on unlabelled
  };
  // Decade grid lines (and minor 2..9 ticks) with labels.
  for (int d = x0; d <= x1; ++d) {
    for (int m = 1; m <= (d < x1 ? 9 : 1); ++m) {
      const int x = px(m * std::pow(10.0, d));
      algo::render_line(image, x, kTop, x, kTop + plotH, m == 1 ? grid : white);
      if (m > 1) algo::render_line(image, x, kTop + plotH - 4, x, kTop + plotH, black);
    }
    char label[32];
    std::snprintf(label, sizeof(label), "%g", std::pow(10.0, d));
    text(px(std::pow(10.0, d)), kTop + plotH + 18, label, 14, algo::TextAlignX::Center,
         algo::TextAlignY::Center);
  }
  for (int d = y0; d <= y1; ++d) {
    for (int m = 1; m <= (d < y1 ? 9 : 1); ++m) {
      const int y = py(m * std::pow(10.0, d));
      algo::render_line(image, kLeft, y, kLeft + plotW, y, m == 1 ? grid : white);
      if (m > 1) algo::render_line(image, kLeft, y, kLeft + 4, y, black);
    }
    char label[32];
    std::snprintf(label, sizeof(label), "%g", std::pow(10.0, d));
    text(kLeft - 8, py(std::pow(10.0, d)), label, 14, algo::TextAlignX::Right,
         algo::TextAlignY::Center);
  }
  algo::render_box(image, kLeft, kTop, kLeft + plotW, kTop + plotH, black);
  text(kLeft + plotW / 2, kHeight - 18, "GPU time per frame (ms, median)", 16,
       algo::TextAlignX::Center, algo::TextAlignY::Center);
  text(12, kTop - 20, "relative RMSE vs reference (seed 002: after the best affine fit)", 16,
       algo::TextAlignX::Left, algo::TextAlignY::Center);
  text(kWidth / 2, 22, title, 18, algo::TextAlignX::Center, algo::TextAlignY::Center);

  for (size_t s = 0; s < order.size(); ++s) {
    const float* colour = kPalette[s % (sizeof(kPalette) / sizeof(kPalette[0]))];
    std::vector<Point>& points = series[order[s]];
    std::sort(points.begin(), points.end(),
              [](const Point& a, const Point& b) { return a.ms < b.ms; });
    for (size_t i = 0; i < points.size(); ++i) {
      const int x = px(points[i].ms), y = py(points[i].error);
      if (i > 0) {
        algo::render_line(image, px(points[i - 1].ms), py(points[i - 1].error), x, y, {colour, 3},
                          true);
      }
      algo::render_box(image, x - 3, y - 3, x + 3, y + 3, {colour, 3}, true);
      // The setting's first number ("16" of "16 samples", "800" of "tau 800") by its point.
      const std::string& setting = points[i].setting;
      const size_t start = setting.find_first_of("0123456789");
      if (start != std::string::npos) {
        text(x + 6, y - 6, setting.substr(start, setting.find(' ', start) - start), 11,
             algo::TextAlignX::Left, algo::TextAlignY::Bottom);
      }
    }
    const int ly = kTop + 12 + int(s) * 24;
    algo::render_box(image, kLeft + plotW + 20, ly - 5, kLeft + plotW + 32, ly + 5, {colour, 3},
                     true);
    text(kLeft + plotW + 40, ly, order[s], 14, algo::TextAlignX::Left, algo::TextAlignY::Center);
  }

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
