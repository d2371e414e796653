#pragma once
// The report's plot as data, before anyone draws it: one panel per effect, each with its own
// error definition on the y axis, its series (one per method, in order of cost), its Pareto
// front, and a place for every point's label that collides with no other label or point.
// Both the gnuplot script (gnuplot_plot.h) and the built-in drawing (error_plot.cpp) draw
// exactly this, so they show the same thing.
#include <string>
#include <vector>

#include "report_table.h"

namespace ocean::report {

struct PlotPoint {
  double ms = 0.0, error = 0.0;
  std::string label;           // the setting's first number ("16" of "16 samples")
  bool labelled = false;       // false: no free place was found; the table still has it
  int labelX = 0, labelY = 0;  // the label's lower-left corner, canvas pixels (y down)
  bool pareto = false;         // no other point of the panel is both faster and more accurate
};

struct PlotSeries {
  std::string method;
  std::vector<PlotPoint> points;  // by time
};

struct PlotPanel {
  std::string title;      // the effect
  std::string errorAxis;  // the y axis: which error, against what
  std::vector<PlotSeries> series;
  int x0 = 0, x1 = 1, y0 = 0, y1 = 1;                 // decades of the axes: 10^x0 .. 10^x1 ms
  int left = 0, top = 0, width = 0, height = 0;       // the plot area, canvas pixels
  int legendX = 0;                                    // the legend's left edge
  int px(double ms) const;                            // canvas pixel of a time
  int py(double error) const;                         // canvas pixel of an error
  std::vector<const PlotPoint*> paretoFront() const;  // by time
};

struct PlotLayout {
  int width = 0, height = 0;  // canvas pixels
  std::string title;
  std::string timeLabel;  // the x axis's
  std::vector<PlotPanel> panels;
};

// Which time the x axis shows: the one measured here (Row::medianMs, llvmpipe where no GPU is),
// or the cost model's estimate on a GPU class (Row::estimatedMs, docs/gpu_cost.md).
enum class TimeAxis { Measured, Estimated };

// Label glyph metrics both renderers are set up to match (DejaVu Sans at this size).
inline constexpr int kLabelFontPx = 11;
inline constexpr int kLabelCharPx = 7;
inline constexpr int kParetoRingPx = 9;  // radius of the ring that marks a Pareto point

// Rows without a positive time and a positive finite error for their panel are left out.
// False with a message when no row can be plotted.
bool layoutErrorPlot(const std::string& title, const std::vector<Row>& rows, PlotLayout& layout,
                     std::string& error, TimeAxis axis = TimeAxis::Measured);

}  // namespace ocean::report
