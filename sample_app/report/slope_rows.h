#pragma once
// The report's rows for seabed caustics on sloped receivers (slope_comparison.h): both water
// lookups per slope, and the physical model as the comparison's own check.
#include <string>
#include <vector>

#include <postfx/postfx.h>
#include <slope_comparison.h>

#include "report_table.h"

namespace ocean::report {

// Report rows for every slope in `slopes` (degrees; slope 0 once, the others facing toward and
// away from the sun), both lookups each.
bool measureSlopedCaustics(const postfx::FrameDesc& hostFrame,
                           const validation::SlopeSettings& settings,
                           const std::vector<double>& slopes, std::vector<Row>& rows,
                           std::string& note, std::string& error);

}  // namespace ocean::report
