#include "slope_rows.h"

#include <algorithm>
#include <cstdio>

namespace ocean::report {

using validation::SlopeCase;
using validation::SlopeLookup;

bool measureSlopedCaustics(const postfx::FrameDesc& hostFrame,
                           const validation::SlopeSettings& settings,
                           const std::vector<double>& slopes, std::vector<Row>& rows,
                           std::string& note, std::string& error) {
  std::vector<validation::SlopeCase> cases;
  for (double slope : slopes) {
    const std::vector<int> facings = slope == 0.0 ? std::vector<int>{1} : std::vector<int>{1, -1};
    if (!validation::measureSlope(hostFrame, settings, slope, facings, cases, error)) return false;
  }
  double worstError = 0.0;
  std::uint64_t rays = 0;
  bool converged = true;
  for (const validation::SlopeCase& c : cases) {
    worstError = std::max(worstError, c.referenceMedianError);
    rays += c.facing > 0 ? c.referenceRays : 0;  // one trace per slope
    converged = converged && c.referenceConverged;
    char setting[64];
    if (c.slopeDegrees == 0.0)
      std::snprintf(setting, sizeof(setting), "slope 0 (control)");
    else
      std::snprintf(setting, sizeof(setting), "slope %.0f, %s", c.slopeDegrees,
                    c.facing > 0 ? "facing the sun" : "facing away");
    for (const validation::SlopeLookup* lookup : {&c.alongLight, &c.triplanar}) {
      const bool triplanar = lookup == &c.triplanar;
      Row row;
      row.pass = "caustics";
      row.method = triplanar ? "ray deviation on a slope, tri-planar walls"
                             : "ray deviation on a slope, along the light";
      row.setting = setting;
      row.medianMs = lookup->run.medianMs;
      row.estimatedMs = lookup->run.estimated(postfx::Pass::Caustics);
      row.floorMs = lookup->run.floorMs;
      row.affineRmse = lookup->stats.affineRmse;  // omega has no absolute scale
      row.correlation = lookup->stats.correlation;
      char text[200];
      std::snprintf(text, sizeof(text),
                    "n.L %.2f; no pattern %.3f; reference noise %.3f; tri-planar minus "
                    "along-light %+.3f (noise sd %.4f)",
                    c.normalDotLight, c.uniform.affineRmse, c.referenceNoise,
                    c.triplanar.stats.affineRmse - c.alongLight.stats.affineRmse,
                    c.differenceNoise);
      row.note = text;
      rows.push_back(row);
    }
    if (!c.physical.run.raw.empty()) {
      Row row;
      row.pass = "caustics";
      row.method = "wavefront area ratio on a slope (check of the comparison)";
      row.setting = setting;
      row.medianMs = c.physical.run.medianMs;
      row.estimatedMs = c.physical.run.estimated(postfx::Pass::Caustics);
      row.floorMs = c.physical.run.floorMs;
      row.relativeRmse = c.physical.stats.relativeRmse;
      row.affineRmse = c.physical.stats.affineRmse;  // the plot's slope panel compares on it
      row.correlation = c.physical.stats.correlation;
      char text[160];
      std::snprintf(text, sizeof(text),
                    "grid %d, incl. irradiance pass; uses neither lookup in its window; no "
                    "pattern %.3f; after affine fit %.3f",
                    settings.physicalGrid, c.uniform.relativeRmse, c.physical.stats.affineRmse);
      row.note = text;
      rows.push_back(row);
    }
  }
  char text[480];
  std::snprintf(text, sizeof(text),
                "Caustics on slopes: a plane %.1f m below the level at the view centre, tilted "
                "about the world z axis and seen face-on from %.1f m (%d x %d pixels, bins of "
                "%d x %d pixels on the plane), the sun at the frame's elevation turned to the "
                "tilt's azimuth; reference: %.3g rays traced through the GPU's water texture onto "
                "each plane, worst median per-bin error %.2g%s. Errors after the best affine fit "
                "(ray deviation's omega has no scale).",
                settings.receiverDepth, settings.viewDistance, settings.width, settings.height,
                settings.binPixels, settings.binPixels, double(rays), worstError,
                converged ? "" : " (ray cap reached)");
  note = text;
  return true;
}

}  // namespace ocean::report
