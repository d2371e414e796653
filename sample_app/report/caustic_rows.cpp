#include "caustic_rows.h"

#include <cmath>
#include <cstdio>
#include <optional>

#include <error_metrics.h>
#include <pass_runner.h>

namespace ocean::report {
namespace {

using validation::compareWithReference;
using validation::contrast;
using validation::ErrorStats;

bool measureOneSize(const postfx::FrameDesc& hostFrame, const CausticReportSettings& sizeSettings,
                    std::vector<Row>& rows, std::string& note, std::string& error) {
  const validation::FlatSeabedSettings& settings = sizeSettings.seabed;
  std::fprintf(stderr, "report: caustics at %dx%d: tracing the seabed reference\n", settings.width,
               settings.height);
  validation::FlatSeabedComparison seabed;
  if (!seabed.prepare(hostFrame, settings, error)) return false;
  const ocean::reference::ReferenceResult& reference = seabed.reference();
  const ocean::reference::ReferenceDesc& desc = seabed.desc();
  const std::vector<double>& truth = seabed.truth();
  const double truthStreaks = seabed.streakRatio(truth);
  char text[400];
  std::snprintf(
      text, sizeof(text),
      "Caustics at %dx%d: flat seabed %.1f m below the level seen from above, %d x %d "
      "bins of %.3f x %.3f m; reference: %.3g rays traced through the GPU's water texture "
      "(level 0) in double, median per-bin error %.2g%s; its streak ratio (gradient "
      "energy across / along the sun's azimuth) %.2f.",
      settings.width, settings.height, settings.receiverDepth, desc.bins.countX, desc.bins.countZ,
      desc.bins.binSize, desc.bins.binSizeZ, double(reference.rays),
      reference.receivers[0].medianRelativeError, reference.converged ? "" : " (ray cap reached)",
      truthStreaks);
  note = text;

  // A model's per-frame pass before the caustics: part of its cost. The models that have one
  // compute irradiance, so their error has an absolute scale.
  struct PrePass {
    postfx::Pass pass;
    const char* label;
  };
  struct Variant {
    std::string method, setting;
    postfx::CausticsSettings caustics;
    bool physical;
    std::optional<PrePass> prePass;
  };
  std::vector<Variant> variants;
  // Tile irradiance: the default (128 texels, 4 layers, 1 point per texel, half-resolution
  // lookups), then one setting changed at a time.
  struct TileVariant {
    int resolution, layers, pointsPerTexel;
    postfx::CausticsLookupResolution lookup;
  };
  constexpr auto kHalf = postfx::CausticsLookupResolution::Half;
  constexpr auto kFull = postfx::CausticsLookupResolution::Full;
  for (const TileVariant& t : {TileVariant{128, 4, 1, kHalf}, TileVariant{128, 4, 1, kFull},
                               TileVariant{128, 4, 2, kFull}, TileVariant{64, 4, 1, kHalf},
                               TileVariant{256, 4, 1, kHalf}, TileVariant{128, 8, 1, kHalf}}) {
    const bool isDefault =
        t.resolution == 128 && t.layers == 4 && t.pointsPerTexel == 1 && t.lookup == kHalf;
    Variant v{isDefault ? "tile irradiance (default)" : "tile irradiance",
              "tiles " + std::to_string(t.resolution) + ", " + std::to_string(t.layers) +
                  " layers, " + std::to_string(t.pointsPerTexel) + " pt/texel, " +
                  (t.lookup == kHalf ? "half-res lookups" : "full-res lookups"),
              postfx::CausticsSettings{}, false,
              PrePass{postfx::Pass::TileIrradiance, "tile pre-pass"}};
    v.caustics.model = postfx::CausticsModel::TileIrradiance;
    v.caustics.tileResolution = t.resolution;
    v.caustics.tileDepthLayers = t.layers;
    v.caustics.tilePointsPerTexel = t.pointsPerTexel;
    v.caustics.tileLookupResolution = t.lookup;
    variants.push_back(v);
  }
  postfx::CausticsSettings rayDeviation;
  rayDeviation.model = postfx::CausticsModel::RayDeviation;
  for (float reflection : {0.0f, 0.25f}) {
    if (!sizeSettings.everyModel) break;
    for (float tau : {100.0f, 400.0f, 800.0f, 3200.0f}) {
      Variant v{
          reflection > 0.0f ? "ray deviation, reflection 0.25" : "ray deviation, refraction only",
          "tau " + std::to_string(int(tau)), rayDeviation, false, std::nullopt};
      v.caustics.tau = tau;
      v.caustics.reflectionWeight = reflection;
      variants.push_back(v);
    }
  }
  for (float cut : {0.0f, 0.3f}) {
    if (!sizeSettings.everyModel) break;
    Variant v{"ray deviation, cascade cut-off",
              "cut " + std::to_string(cut).substr(0, 3) + " tau 800", rayDeviation, false,
              std::nullopt};
    v.caustics.minCascadeContrast = cut;
    variants.push_back(v);
  }
  for (int grid : sizeSettings.physicalGrids) {
    if (!sizeSettings.everyModel && grid != 256) continue;
    Variant v{"wavefront area ratio", "grid " + std::to_string(grid), postfx::CausticsSettings{},
              true, PrePass{postfx::Pass::WavefrontAreaRatio, "irradiance pass"}};
    v.caustics.model = postfx::CausticsModel::WavefrontAreaRatio;
    v.caustics.gridResolution = grid;
    variants.push_back(v);
  }

  const std::vector<double> uniform(truth.size(), 1.0);
  const validation::ErrorStats flat = validation::compareWithReference(uniform, truth);
  Row flatRow;
  flatRow.pass = "caustics";
  flatRow.method = "no caustics (uniform light)";
  flatRow.setting = "-";
  flatRow.width = settings.width;
  flatRow.height = settings.height;
  flatRow.contrast = 0.0;
  flatRow.referenceContrast = contrast(truth);
  flatRow.relativeRmse = flat.relativeRmse;
  flatRow.affineRmse = flat.affineRmse;
  flatRow.note = "the error of drawing no caustic pattern at all";
  rows.push_back(flatRow);
  for (size_t k = 0; k < variants.size(); ++k) {
    const Variant& v = variants[k];
    std::fprintf(stderr, "report: caustics at %dx%d, %s, %s (%zu/%zu)\n", settings.width,
                 settings.height, v.method.c_str(), v.setting.c_str(), k + 1, variants.size());
    postfx::CreateDesc create;
    create.features = v.physical ? postfx::Feature::WavefrontAreaRatio : postfx::Feature::None;
    validation::PassRun run;
    std::vector<double> binned;
    if (!seabed.run(create, v.caustics, sizeSettings.timedFrames, run, binned, error)) return false;
    Row row;
    row.pass = "caustics";
    row.method = v.method;
    row.setting = v.setting;
    row.width = settings.width;
    row.height = settings.height;
    row.medianMs = run.medianMs;
    row.estimatedMs = run.estimated(postfx::Pass::Caustics);
    row.floorMs = run.floorMs;
    if (v.prePass) {
      const double prePassMs = run.stats.pass(v.prePass->pass).medianMs;
      row.medianMs += prePassMs;
      row.estimatedMs += run.estimated(v.prePass->pass);
      char cost[160];
      std::snprintf(cost, sizeof(cost), "incl. %s %.2f ms; ", v.prePass->label, prePassMs);
      row.note = cost;
      // The physical window is continued by the tile irradiance: its pre-pass runs too.
      const postfx::PassStats& tile = run.stats.pass(postfx::Pass::TileIrradiance);
      if (v.prePass->pass != postfx::Pass::TileIrradiance && !tile.skipped) {
        row.medianMs += tile.medianMs;
        row.estimatedMs += run.estimated(postfx::Pass::TileIrradiance);
        std::snprintf(cost, sizeof(cost), "incl. tile pre-pass %.2f ms; ", tile.medianMs);
        row.note += cost;
      }
    }
    char streaks[96];
    std::snprintf(streaks, sizeof(streaks), "streak ratio %.2f (traced %.2f)",
                  seabed.streakRatio(binned), truthStreaks);
    row.note += streaks;
    const validation::ErrorStats stats = validation::compareWithReference(binned, truth);
    // Ray deviation's omega has no absolute scale; the irradiance models' does.
    if (v.prePass) row.relativeRmse = stats.relativeRmse;
    // Every model's pattern error too: the plot's seabed panel compares them all on it.
    row.affineRmse = stats.affineRmse;
    row.correlation = stats.correlation;
    row.contrast = contrast(binned);
    row.referenceContrast = flatRow.referenceContrast;
    rows.push_back(row);
  }
  return true;
}

}  // namespace

bool measureCaustics(const postfx::FrameDesc& hostFrame,
                     const std::vector<CausticReportSettings>& sizes, std::vector<Row>& rows,
                     std::string& note, std::string& error) {
  for (const CausticReportSettings& settings : sizes) {
    std::string sizeNote;
    if (!measureOneSize(hostFrame, settings, rows, sizeNote, error)) return false;
    note += (note.empty() ? "" : "\n\n") + sizeNote;
  }
  return true;
}

}  // namespace ocean::report
