#pragma once
// The report's plot: error against GPU time, both axes logarithmic, one panel per effect with
// its error definition on the y axis, one poly-line per method (its settings in order of cost)
// and the panel's Pareto front; written as PNG through OpenImageIO.
#include <string>
#include <vector>

#include "plot_layout.h"
#include "report_table.h"

namespace ocean::report {

enum class PlotBackend {
  Auto,     // gnuplot when it is on PATH (and draws), else the built-in drawing
  BuiltIn,  // lines and text drawn by OpenImageIO; labels need DejaVu Sans (else unlabelled)
};

// With gnuplot, its script is kept as `path` with the extension .gp. `used` (optional) says
// which drawing was written: "gnuplot" or "built-in".
// `axis`: the measured time or the cost model's estimate (plot_layout.h).
bool writeErrorPlot(const std::string& path, const std::string& title, const std::vector<Row>& rows,
                    std::string& error, PlotBackend backend = PlotBackend::Auto,
                    std::string* used = nullptr, TimeAxis axis = TimeAxis::Measured);

}  // namespace ocean::report
