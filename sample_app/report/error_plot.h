#pragma once
// The report's plot: error against GPU time, both axes logarithmic, one coloured poly-line per
// method (its settings in order of cost), written as PNG through OpenImageIO.
#include <string>
#include <vector>

#include "report_table.h"

namespace ocean::report {

// Rows with a positive time and a positive finite plotted error become points; rows of the same
// method form one series. Labels need a TrueType font (DejaVu Sans); without one the plot is
// drawn unlabelled rather than not at all.
bool writeErrorPlot(const std::string& path, const std::string& title, const std::vector<Row>& rows,
                    std::string& error);

}  // namespace ocean::report
