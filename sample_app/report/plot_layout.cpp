#include "plot_layout.h"

#include <algorithm>
#include <cmath>
#include <functional>

namespace ocean::report {
namespace {

// Which rows a panel takes and which of their errors it plots. A model added to an effect's
// pass joins that effect's panel with the same error definition; a pass no panel names gets a
// panel of its own (the last entry).
struct PanelRule {
  std::string title, errorAxis;
  std::function<bool(const Row&)> takes;
  std::function<double(const Row&)> error;
  // Rows this panel answers for without plotting them (other sizes of the same comparison,
  // which the table lists); they get no panel of their own.
  std::function<bool(const Row&)> claims = [](const Row&) { return false; };
};

bool onSlope(const Row& row) {
  return row.method.find("on a slope") != std::string::npos;
}

bool onFlatSeabed(const Row& row) {
  return row.pass == "caustics" && !onSlope(row);
}

std::vector<PanelRule> panelRules(const std::vector<Row>& rows) {
  // The flat seabed is measured at several sizes; the plot shows the largest (1280x720 in a
  // full run: the pattern's error where it is finest).
  int width = 0, height = 0;
  for (const Row& r : rows)
    if (onFlatSeabed(r) && r.width > width) width = r.width, height = r.height;
  const std::string flatTitle = width > 0
                                    ? "seabed caustics (flat seabed, " + std::to_string(width) +
                                          "x" + std::to_string(height) + ")"
                                    : "seabed caustics (flat seabed)";
  // The seabed's ray-deviation factor has no absolute scale: every seabed model is compared
  // after its best affine fit, so the panel has one definition for all of them.
  const std::string pattern = "relative RMSE after the best fit a x + b, against traced light";
  return {
      {flatTitle, pattern, [width](const Row& r) { return onFlatSeabed(r) && r.width == width; },
       [](const Row& r) { return r.affineRmse; }, [](const Row& r) { return onFlatSeabed(r); }},
      {"seabed caustics on slopes", pattern,
       [](const Row& r) { return r.pass == "caustics" && onSlope(r); },
       [](const Row& r) { return r.affineRmse; }},
      {"god rays", "relative RMSE against the dense march",
       [](const Row& r) { return r.pass == "god_rays"; },
       [](const Row& r) { return r.relativeRmse; }},
      {"object caustics", "relative RMSE of the map against exact ray tracing",
       [](const Row& r) { return r.pass == "object_caustics"; },
       [](const Row& r) { return r.relativeRmse; }},
      {"local water (the pool)", "relative RMSE of the pattern against traced light",
       [](const Row& r) { return r.pass == "local_water"; },
       [](const Row& r) { return r.relativeRmse; }},
      {"volume caustics (glass sphere in water)",
       "relative RMSE inside the cone against the traced beams",
       [](const Row& r) { return r.pass == "volume_caustics"; },
       [](const Row& r) { return r.relativeRmse; }},
  };
}

// Decade range [lo, hi] covering every value, at least one decade wide.
void decades(const std::vector<double>& values, int& lo, int& hi) {
  double mn = HUGE_VAL, mx = 0.0;
  for (double v : values) mn = std::min(mn, v), mx = std::max(mx, v);
  lo = int(std::floor(std::log10(mn)));
  hi = int(std::ceil(std::log10(mx)));
  if (hi <= lo) hi = lo + 1;
}

struct Box {
  int x0, y0, x1, y1;
  bool overlaps(const Box& o) const { return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1; }
};

// Greedy placement: each label tries eight spots around its point, nearest first, and takes
// the first that overlaps no placed label, no point and stays inside the plot area.
void placeLabels(PlotPanel& panel) {
  // A point's marker, or the ring round a point of the Pareto front (gnuplot's pt 6 ps 2).
  std::vector<Box> taken;
  for (const PlotSeries& s : panel.series)
    for (const PlotPoint& p : s.points) {
      const int r = p.pareto ? kParetoRingPx : 4;
      taken.push_back(
          {panel.px(p.ms) - r, panel.py(p.error) - r, panel.px(p.ms) + r, panel.py(p.error) + r});
    }
  const Box area{panel.left, panel.top, panel.left + panel.width, panel.top + panel.height};
  for (PlotSeries& s : panel.series) {
    for (PlotPoint& p : s.points) {
      if (p.label.empty()) continue;
      const int w = kLabelCharPx * int(p.label.size()), h = kLabelFontPx;
      const int x = panel.px(p.ms), y = panel.py(p.error);
      const int d = p.pareto ? kParetoRingPx + 1 : 6;  // clear of the marker or ring
      const int spots[][2] = {{d, -d - h},      {d, d},      {-d - w, -d - h}, {-d - w, d},
                              {-w / 2, -d - h}, {-w / 2, d}, {d, -h / 2},      {-d - w, -h / 2}};
      for (const auto& spot : spots) {
        const Box box{x + spot[0], y + spot[1], x + spot[0] + w, y + spot[1] + h};
        if (box.x0 < area.x0 || box.x1 > area.x1 || box.y0 < area.y0 || box.y1 > area.y1) continue;
        if (std::any_of(taken.begin(), taken.end(), [&](const Box& t) { return t.overlaps(box); }))
          continue;
        taken.push_back(box);
        p.labelled = true;
        p.labelX = box.x0;
        p.labelY = box.y1;
        break;
      }
    }
  }
}

}  // namespace

int PlotPanel::px(double ms) const {
  return left + int(std::lround((std::log10(ms) - x0) / (x1 - x0) * width));
}
int PlotPanel::py(double e) const {
  return top + height - int(std::lround((std::log10(e) - y0) / (y1 - y0) * height));
}

std::vector<const PlotPoint*> PlotPanel::paretoFront() const {
  std::vector<const PlotPoint*> front;
  for (const PlotSeries& s : series)
    for (const PlotPoint& p : s.points)
      if (p.pareto) front.push_back(&p);
  std::sort(front.begin(), front.end(),
            [](const PlotPoint* a, const PlotPoint* b) { return a->ms < b->ms; });
  return front;
}

bool layoutErrorPlot(const std::string& title, const std::vector<Row>& rows, PlotLayout& layout,
                     std::string& error, TimeAxis axis) {
  auto timeOf = [axis](const Row& row) {
    return axis == TimeAxis::Measured ? row.medianMs : row.estimatedMs;
  };
  std::vector<PanelRule> rules = panelRules(rows);
  std::vector<bool> claimed(rows.size(), false);
  for (size_t i = 0; i < rows.size(); ++i)
    for (const PanelRule& rule : rules)
      claimed[i] = claimed[i] || rule.takes(rows[i]) || rule.claims(rows[i]);
  for (size_t i = 0; i < rows.size(); ++i) {
    if (claimed[i]) continue;
    const std::string pass = rows[i].pass;
    rules.push_back({pass, "error against its reference",
                     [pass](const Row& r) { return r.pass == pass; },
                     [](const Row& r) { return r.plottedError(); }});
    for (size_t j = i; j < rows.size(); ++j) claimed[j] = claimed[j] || rows[j].pass == pass;
  }

  layout = PlotLayout{};
  layout.title = title;
  layout.timeLabel = axis == TimeAxis::Measured
                         ? "GPU time per frame (ms, median)"
                         : "ESTIMATED GPU time per frame, RTX 3060 class at 1920x1080 (ms)";
  for (const PanelRule& rule : rules) {
    PlotPanel panel;
    panel.title = rule.title;
    panel.errorAxis = rule.errorAxis;
    std::vector<double> times, errors;
    for (const Row& row : rows) {
      const double e = rule.error(row);
      if (!rule.takes(row) || !(timeOf(row) > 0.0) || !(e > 0.0) || !std::isfinite(e)) continue;
      auto found = std::find_if(panel.series.begin(), panel.series.end(),
                                [&](const PlotSeries& s) { return s.method == row.method; });
      if (found == panel.series.end()) {
        panel.series.push_back({row.method, {}});
        found = panel.series.end() - 1;
      }
      PlotPoint point;
      point.ms = timeOf(row);
      point.error = e;
      const size_t start = row.setting.find_first_of("0123456789");
      if (start != std::string::npos)
        point.label = row.setting.substr(start, row.setting.find_first_of(" ,", start) - start);
      found->points.push_back(point);
      times.push_back(point.ms);
      errors.push_back(e);
    }
    if (times.empty()) continue;
    for (PlotSeries& s : panel.series)
      std::sort(s.points.begin(), s.points.end(),
                [](const PlotPoint& a, const PlotPoint& b) { return a.ms < b.ms; });
    for (PlotSeries& s : panel.series)
      for (PlotPoint& p : s.points) {
        p.pareto = true;
        for (const PlotSeries& t : panel.series)
          for (const PlotPoint& q : t.points)
            if (&q != &p && q.ms <= p.ms && q.error <= p.error &&
                (q.ms < p.ms || q.error < p.error))
              p.pareto = false;
      }
    decades(times, panel.x0, panel.x1);
    decades(errors, panel.y0, panel.y1);
    layout.panels.push_back(std::move(panel));
  }
  if (layout.panels.empty()) {
    error = "nothing to plot: no row has both a time and an error";
    return false;
  }
  // Two panels a row; each panel: plot area, axis labels left and below, legend on the right.
  constexpr int kPanelW = 900, kPanelH = 520, kTitleH = 50;
  constexpr int kLeft = 80, kTop = 44, kBottom = 64, kLegendW = 370;
  const int columns = layout.panels.size() > 1 ? 2 : 1;
  const int panelRows = int(layout.panels.size() + 1) / columns;
  layout.width = columns * kPanelW;
  layout.height = kTitleH + panelRows * kPanelH;
  for (size_t i = 0; i < layout.panels.size(); ++i) {
    PlotPanel& panel = layout.panels[i];
    const int ox = int(i) % columns * kPanelW, oy = kTitleH + int(i) / columns * kPanelH;
    panel.left = ox + kLeft;
    panel.top = oy + kTop;
    panel.width = kPanelW - kLeft - kLegendW;
    panel.height = kPanelH - kTop - kBottom;
    panel.legendX = panel.left + panel.width + 16;
    placeLabels(panel);
  }
  return true;
}

}  // namespace ocean::report
