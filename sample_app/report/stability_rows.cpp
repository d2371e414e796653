#include "stability_rows.h"

#include <cstdio>
#include <sstream>

#include <plugin_setup.h>
#include <renderer.h>
#include <scene_setup.h>
#include <view_flags.h>

#include "table_text.h"

namespace ocean::report {
namespace {

std::string number(double value, int digits) {
  char text[48];
  std::snprintf(text, sizeof text, "%.*g", digits, value);
  return text;
}

constexpr StabilityPass kPasses[] = {
    StabilityPass::TileCaustics,       StabilityPass::RayDeviationCaustics,
    StabilityPass::WavefrontAreaRatio, StabilityPass::GodRays,
    StabilityPass::ObjectCaustics,     StabilityPass::FilteredObjectCaustics};

}  // namespace

bool measureStability(const Options& options, const StabilityReportSettings& settings,
                      std::vector<StabilityRow>& rows, std::string& note, std::string& error) {
  Preset preset;
  if (!resolveView(options, preset, error)) return false;
  ocean_scene::Model scene;
  if (!buildScene(options.models, scene, error, options.modelLimits)) return false;
  RenderSettings render;
  render.width = settings.width;
  render.height = settings.height;
  render.waterResolution = settings.waterResolution;
  auto renderer = Renderer::create(render, scene, error);
  if (!renderer) return false;
  // The object caustics need the casters and the receiver map whatever the command line said.
  Options hostOptions = options;
  hostOptions.objectCaustics = true;
  auto plugin = PluginSetup::create(*renderer, hostOptions, false, error);
  if (!plugin) return false;
  StabilityHost host{*renderer, *plugin, scene, {preset.camera, preset.sun, options.timeSeconds}};

  const StabilityMotion motions[] = {cameraMotion(), timeMotion()};
  // One reference sequence per (reference, motion), shared by the rows that compare with it.
  std::optional<AddedLightChange> truths[2][2];
  if (settings.references) {
    for (int m = 0; m < 2; ++m) {
      for (StabilityReference reference :
           {StabilityReference::TracedCaustics, StabilityReference::DenseGodRays}) {
        std::fprintf(stderr, "report: temporal stability, %s reference, %s (%d frames)\n",
                     stabilityReferenceName(reference), describeMotion(motions[m]).c_str(),
                     settings.frames);
        AddedLightFrames frames;
        if (!renderReferenceSequence(host, reference, motions[m], settings.frames,
                                     settings.reference, frames, error))
          return false;
        truths[int(reference)][m] = addedLightChange(frames);
      }
    }
  }
  int done = 0;
  for (StabilityPass pass : kPasses) {
    for (int m = 0; m < 2; ++m) {
      std::fprintf(stderr, "report: temporal stability, %s, %s (%d/%zu)\n", stabilityPassName(pass),
                   describeMotion(motions[m]).c_str(), ++done, std::size(kPasses) * 2);
      AddedLightFrames frames;
      if (!renderPassSequence(host, pass, motions[m], settings.frames, frames, error)) return false;
      StabilityRow row;
      row.pass = stabilityPassName(pass);
      row.motion = describeMotion(motions[m]);
      row.plugin = addedLightChange(frames);
      const std::optional<StabilityReference> reference = stabilityReference(pass);
      if (!reference) {
        row.reference = "none for a whole frame";
      } else if (!settings.references) {
        row.reference = std::string(stabilityReferenceName(*reference)) + ": left out (--quick)";
      } else {
        row.reference = stabilityReferenceName(*reference);
        row.truth = truths[int(*reference)][m];
      }
      rows.push_back(row);
    }
  }

  char text[1024];
  std::snprintf(text, sizeof text,
                "%dx%d pixels, water %d texels per cascade, %d frames per sequence (%d "
                "frame-to-frame changes), starting at the preset's camera and t = %g s. Change: "
                "mean |luminance difference| of the added light between consecutive frames "
                "over its mean luminance, over the pixels the pass lights in either frame (p99: "
                "the 99th percentile of that difference over the same mean).",
                settings.width, settings.height, settings.waterResolution, settings.frames,
                settings.frames - 1, options.timeSeconds);
  note = text;
  if (settings.references) {
    std::fprintf(stderr, "report: temporal stability, traced reference noise (2 seeds)\n");
    AddedLightFrames pair;
    if (!tracedNoisePair(host, settings.reference, pair, error)) return false;
    const AddedLightChange noise = addedLightChange(pair);
    std::snprintf(text, sizeof text,
                  " References: the traced caustics with %d batches and seed %llu in every "
                  "frame (common random numbers); the same frame traced with the next seed "
                  "changes by %.4f (p99 %.3f): what the trace's noise alone would add if every "
                  "frame drew new photons, an upper bound of the noise in its change. The "
                  "god rays' dense march: %d segments per pixel, deterministic.",
                  settings.reference.traceBatches, settings.reference.seed, noise.mean, noise.p99,
                  settings.reference.godRaySamples);
    note += text;
  } else {
    note +=
        " References left out (--quick): their 8 traced frames and 6 dense marches take "
        "about 4 minutes on 2 cores.";
  }
  return true;
}

bool writeStabilityTables(const std::string& directory, const ReportInfo& info,
                          const StabilityReportSettings& settings,
                          const std::vector<StabilityRow>& rows, const std::string& note,
                          std::string& error) {
  std::ostringstream csv;
  csv << "pass,motion,plugin_change_mean,plugin_change_p99,plugin_mean_light,reference,"
         "reference_change_mean,reference_change_p99,plugin_over_reference\n";
  std::ostringstream md;
  md << "# Temporal stability\n\n"
     << measuredLine(info) << "\n\nGenerated by `ocean_sample report` on " << info.device << " ("
     << settings.width << "x" << settings.height
     << "). Ratios of changes, not timings: see docs/temporal_stability.md.\n\n"
     << note << "\n\n"
     << "| pass | motion | plugin change (mean) | plugin change (p99) | reference | reference "
        "change (mean) | reference change (p99) | plugin / reference (mean) |\n"
     << "|---|---|---|---|---|---|---|---|\n";
  for (const StabilityRow& row : rows) {
    const bool truth = row.truth.has_value() && row.truth->mean > 0.0;
    const std::string ratio = truth ? number(row.plugin.mean / row.truth->mean, 3) : "";
    const std::string truthMean = row.truth ? number(row.truth->mean, 3) : "";
    const std::string truthP99 = row.truth ? number(row.truth->p99, 3) : "";
    csv << csvField(row.pass) << ',' << csvField(row.motion) << ',' << number(row.plugin.mean, 5)
        << ',' << number(row.plugin.p99, 5) << ',' << number(row.plugin.meanLight, 5) << ','
        << csvField(row.reference) << ',' << truthMean << ',' << truthP99 << ',' << ratio << '\n';
    md << "| " << row.pass << " | " << row.motion << " | " << number(row.plugin.mean, 3) << " | "
       << number(row.plugin.p99, 3) << " | " << row.reference << " | " << truthMean << " | "
       << truthP99 << " | " << ratio << " |\n";
  }
  return writeText(directory + "temporal_stability.csv", csv.str(), error) &&
         writeText(directory + "temporal_stability.md", md.str(), error);
}

}  // namespace ocean::report
