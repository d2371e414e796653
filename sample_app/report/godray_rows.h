#pragma once
// The report's god-ray rows: every sample count at full and half resolution, world-grid and
// uniform sampling, each timed and compared with the dense double-precision march
// (reference::renderGodRayReference) of the same frame with ray deviation's factor (the
// RayDeviation model); then the god rays of the TileIrradiance model (the seabed caustics' light
// field, the default) at full, half and quarter resolution against the plugin's own dense march of
// that field (referenceSamples uniform samples per pixel, full resolution).
#include <string>
#include <vector>

#include <postfx/postfx.h>

#include "pass_runner.h"
#include "report_table.h"

namespace ocean::report {

struct GodRayReportSettings {
  int referenceSamples = 2048;  // segments per pixel of the dense march
  int timedFrames = 16;
};

// `host` / `hostFrame`: what the sample handed the plugin for the frame now in its G-buffer.
// Appends rows; `note` gets the reference's convergence. Progress on stderr.
bool measureGodRays(const postfx::CreateDesc& host, const postfx::FrameDesc& hostFrame,
                    const validation::ReportTarget& target, const GodRayReportSettings& settings,
                    std::vector<Row>& rows, std::string& note, std::string& error);

}  // namespace ocean::report
