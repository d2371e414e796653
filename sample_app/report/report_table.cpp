#include "report_table.h"

#include <cstdio>
#include <sstream>

#include "table_text.h"

namespace ocean::report {
namespace {

// `digits` significant digits (general format), or fixed with `decimals` when >= 0.
std::string number(double value, int digits, int decimals = -1) {
  if (value != value) return "";
  char text[48];
  if (decimals >= 0) {
    std::snprintf(text, sizeof(text), "%.*f", decimals, value);
  } else {
    std::snprintf(text, sizeof(text), "%.*g", digits, value);
  }
  return text;
}

// "1280x720", or the report's timed size where the row names none.
std::string size(const Row& row, int width, int height) {
  const int w = row.width > 0 ? row.width : width, h = row.width > 0 ? row.height : height;
  return w > 0 ? std::to_string(w) + "x" + std::to_string(h) : "";
}

}  // namespace

std::string measuredLine(const ReportInfo& info) {
  return "Measured " +
         (info.date.empty() ? std::string("on an unknown date") : info.date + " (UTC)") +
         " from code revision `" +
         (info.revision.empty() ? std::string("unknown") : info.revision) + "`.";
}

bool writeCsv(const std::string& path, const ReportInfo& info, const std::vector<Row>& rows,
              std::string& error) {
  std::ostringstream out;
  out << "pass,method,setting,size,median_ms,floor_ms,floor_ratio,estimated_gpu_ms,relative_rmse,"
         "affine_rmse,correlation,contrast,reference_contrast,note\n";
  for (const Row& row : rows) {
    out << csvField(row.pass) << ',' << csvField(row.method) << ',' << csvField(row.setting) << ','
        << size(row, info.width, info.height) << ',' << number(row.medianMs, 6) << ','
        << number(row.floorMs, 6) << ',' << number(row.floorRatio(), 4) << ','
        << number(row.estimatedMs, 5) << ',' << number(row.relativeRmse, 5) << ','
        << number(row.affineRmse, 5) << ',' << number(row.correlation, 5) << ','
        << number(row.contrast, 4) << ',' << number(row.referenceContrast, 4) << ','
        << csvField(row.note) << '\n';
  }
  return writeText(path, out.str(), error);
}

bool anyEstimated(const std::vector<Row>& rows) {
  for (const Row& row : rows)
    if (row.estimatedMs == row.estimatedMs && row.estimatedMs > 0.0) return true;
  return false;
}

std::string estimatePlotFile(const std::string& plotFile) {
  const std::size_t dot = plotFile.rfind('.');
  const std::size_t slash = plotFile.rfind('/');
  const bool extension = dot != std::string::npos && (slash == std::string::npos || dot > slash);
  return extension ? plotFile.substr(0, dot) + "_gpu_estimate" + plotFile.substr(dot)
                   : plotFile + "_gpu_estimate";
}

bool writeMarkdown(const std::string& path, const ReportInfo& info, const std::vector<Row>& rows,
                   const std::string& plotFile, std::string& error) {
  std::ostringstream out;
  out << "# Error against run time\n\n"
      << measuredLine(info) << "\n\n"
      << "Device: " << info.device << ". Passes timed at " << info.width << "x" << info.height
      << " (GPU timer queries, median after warm-up; floor = a pass that reads the same inputs "
         "and writes the same outputs with no math, measured in the same run)"
      << (info.quick ? "; quick run" : "") << ".\n\n"
      << info.referenceNote << "\n\n"
      << "Est. GPU ms: the cost model's ESTIMATE of the same work on the RTX 3060 class, its "
         "per-pixel steps at 1920x1080, the rest as run (docs/gpu_cost.md): not a measurement.\n\n";
  if (!plotFile.empty()) out << "![error against run time](" << plotFile << ")\n\n";
  if (!plotFile.empty() && anyEstimated(rows))
    out << "![error against the estimated GPU time](" << estimatePlotFile(plotFile) << ")\n\n";
  out << "| pass | method | setting | size | median ms | floor ratio | est. GPU ms (RTX 3060, "
         "1080p) | relative RMSE | RMSE after affine fit | correlation | contrast / reference's | "
         "note |\n"
      << "|---|---|---|---|---:|---:|---:|---:|---:|---:|---:|---|\n";
  for (const Row& row : rows) {
    const std::string contrast =
        row.contrast == row.contrast
            ? number(row.contrast, 0, 3) + " / " + number(row.referenceContrast, 0, 3)
            : "";
    out << "| " << row.pass << " | " << row.method << " | " << row.setting << " | "
        << size(row, info.width, info.height) << " | " << number(row.medianMs, 0, 3) << " | "
        << number(row.floorRatio(), 0, 2) << " | " << number(row.estimatedMs, 0, 3) << " | "
        << number(row.relativeRmse, 0, 4) << " | " << number(row.affineRmse, 0, 4) << " | "
        << number(row.correlation, 0, 3) << " | " << contrast << " | " << row.note << " |\n";
  }
  return writeText(path, out.str(), error);
}

}  // namespace ocean::report
