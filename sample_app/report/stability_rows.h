#pragma once
// The report's temporal-stability rows: for every pass (the caustics in each
// model, the god rays, the object caustics with and without their temporal filter) the
// frame-to-frame change of the light it adds under two slow motions (time frozen with the
// camera moving; the camera still with time running), beside its reference's own change over
// the same frames where a reference of the whole frame exists: flicker is change beyond what
// the truth changes. Written to DIR/temporal_stability.{csv,md}.
#include <optional>
#include <string>
#include <vector>

#include <options.h>
#include <report_table.h>
#include <stability_sequence.h>
#include <temporal_stability.h>

namespace ocean::report {

struct StabilityRow {
  std::string pass;    // stabilityPassName
  std::string motion;  // describeMotion
  AddedLightChange plugin;
  std::string reference;                  // its name, or why there is none
  std::optional<AddedLightChange> truth;  // the reference's change over the same frames
};

struct StabilityReportSettings {
  int width = 160, height = 90;  // of the frames measured (the traced reference's cost)
  int waterResolution = 256;
  int frames = 3;          // per sequence: frames - 1 consecutive pairs
  bool references = true;  // false: the plugin's rows only (report --quick)
  ReferenceSequenceSettings reference;
};

// Renders `options`' preset (its camera, sun, time and models) in the current GL context at the
// settings' size. Appends one row per pass and motion; `note` says how the references were made
// and how much of their change their noise could explain. Progress on stderr.
bool measureStability(const Options& options, const StabilityReportSettings& settings,
                      std::vector<StabilityRow>& rows, std::string& note, std::string& error);

bool writeStabilityTables(const std::string& directory, const ReportInfo& info,
                          const StabilityReportSettings& settings,
                          const std::vector<StabilityRow>& rows, const std::string& note,
                          std::string& error);

}  // namespace ocean::report
