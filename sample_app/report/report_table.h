#pragma once
// One row per (pass, method, setting) of the error-against-run-time report, and the two text
// forms it is written in: CSV for tools, a markdown table for docs/measurements.md.
#include <limits>
#include <string>
#include <vector>

namespace ocean::report {

inline constexpr double kNotApplicable = std::numeric_limits<double>::quiet_NaN();

struct Row {
  std::string pass;     // plugin pass timed: "caustics", "god_rays", ...
  std::string method;   // series in the plot, e.g. "god rays, half resolution"
  std::string setting;  // what varies along the series, e.g. "16 samples"
  double medianMs = 0.0;
  double floorMs = 0.0;  // floor pass measured in the same run (same inputs and outputs)
  // The cost model's ESTIMATE of the same work on the RTX 3060 class, its per-pixel steps at
  // 1920x1080 (docs/gpu_cost.md; validation::PassRun::estimatedMs); NaN: not estimated.
  double estimatedMs = kNotApplicable;
  // Error against the CPU reference over the compared pixels:
  double relativeRmse = kNotApplicable;  // sqrt(sum (x - r)^2 / sum r^2), absolute scale
  double affineRmse = kNotApplicable;    // the same after the best fit a x + b (methods whose
                                       // output has no absolute scale, e.g. ray deviation's omega)
  double correlation = kNotApplicable;  // Pearson correlation with the reference
  // Pattern contrast (std / mean over the compared bins) of the pass and of the reference; set
  // where the compared value is itself a pattern (the flat seabed's light relative to flat water).
  double contrast = kNotApplicable, referenceContrast = kNotApplicable;
  // The view the row was measured at (pixels); 0 x 0: the report's timed size (ReportInfo).
  int width = 0, height = 0;
  std::string note;

  double floorRatio() const { return floorMs > 0.0 ? medianMs / floorMs : kNotApplicable; }
  // The error the plot shows: absolute where the method has a scale, else after the fit.
  double plottedError() const { return relativeRmse == relativeRmse ? relativeRmse : affineRmse; }
};

struct ReportInfo {
  std::string device;
  std::string date;           // of the run, YYYY-MM-DD (UTC)
  std::string revision;       // of the code measured (git describe); empty: unknown
  int width = 0, height = 0;  // of the timed passes
  bool quick = false;
  std::string referenceNote;  // how the references were computed and how converged they are
};

// "Measured DATE (UTC) from code revision `REV`." (either part "unknown" where not given).
std::string measuredLine(const ReportInfo& info);

bool writeCsv(const std::string& path, const ReportInfo& info, const std::vector<Row>& rows,
              std::string& error);
bool writeMarkdown(const std::string& path, const ReportInfo& info, const std::vector<Row>& rows,
                   const std::string& plotFile, std::string& error);

// Whether any row has the cost model's estimate (Row::estimatedMs).
bool anyEstimated(const std::vector<Row>& rows);
// The file of the plot against the estimate beside `plotFile` ("x.png": "x_gpu_estimate.png"),
// written where anyEstimated and linked by writeMarkdown.
std::string estimatePlotFile(const std::string& plotFile);

}  // namespace ocean::report
