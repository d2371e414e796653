// ocean_sample report: error against run time of every method and quality setting on the
// default scene. Each pass is timed by the plugin's GPU timers (median after warm-up, with its
// floor) and compared with a CPU reference of the same frame; writes DIR/error_vs_time.csv, a
// markdown table and a log-log plot (PNG through OpenImageIO). Progress on stderr.
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <caustic_rows.h>
#include <error_plot.h>
#include <godray_rows.h>
#include <object_caustic_rows.h>
#include <pass_runner.h>
#include <report_table.h>
#include <slope_rows.h>
#include <stability_rows.h>

#include "commands.h"
#include "headless_session.h"

namespace ocean {
namespace {

// The error-against-run-time rows, on the frame now in `session`'s G-buffer.
bool measureErrorRows(HeadlessSession& session, bool quick, std::vector<report::Row>& rows,
                      report::ReportInfo& info, std::string& error) {
  const postfx::CreateDesc& host = session.plugin->createDesc();
  const postfx::FrameDesc& frame = session.plugin->lastFrame();
  report::ReportTarget target(info.width, info.height);
  report::GodRayReportSettings godRays;
  godRays.referenceSamples = quick ? 1024 : 2048;
  godRays.timedFrames = quick ? 6 : 16;
  std::string godRayNote;
  if (!report::measureGodRays(host, frame, target, godRays, rows, godRayNote, error)) return false;
  report::CausticReportSettings caustics;
  caustics.width = quick ? 160 : 320;
  caustics.height = quick ? 88 : 176;
  caustics.binPixels = quick ? 4 : 8;
  caustics.referenceError = quick ? 0.03 : 0.02;
  caustics.timedFrames = godRays.timedFrames;
  if (quick) caustics.physicalGrids = {64, 128, 256};
  std::string causticNote;
  if (!report::measureCaustics(frame, caustics, rows, causticNote, error)) return false;
  // Slopes: the default water lookup (along the light) against Feature::TriplanarWalls.
  report::SlopeSettings slopes;
  slopes.width = quick ? 96 : 160;
  slopes.height = 96;
  slopes.binPixels = 8;
  // 0.03: at 0.02 the 60 degree plane facing away (n.L 0.16) alone needs 5e7 rays (12 min);
  // --quick leaves 60 degrees out for the same reason (8e6 rays at 0.05).
  slopes.referenceError = quick ? 0.05 : 0.03;
  slopes.timedFrames = godRays.timedFrames;
  slopes.physicalGrid = 256;
  const std::vector<double> slopeAngles =
      quick ? std::vector<double>{0.0, 45.0} : std::vector<double>{0.0, 30.0, 45.0, 60.0};
  std::string slopeNote;
  if (!report::measureSlopedCaustics(frame, slopes, slopeAngles, rows, slopeNote, error))
    return false;
  std::string objectNote;
  if (!report::measureObjectCaustics(target, report::objectCausticSweep(quick), rows, objectNote,
                                     error))
    return false;
  info.referenceNote = causticNote + "\n\n" + slopeNote + "\n\n" + godRayNote + "\n\n" + objectNote;
  return true;
}

}  // namespace

int runReport(const Options& given) {
  Options options = given;
  // Small enough for the CPU references to converge in minutes; --quick for a smoke run.
  options.width = given.quick ? 160 : 320;
  options.height = given.quick ? 90 : 180;
  // --only stability: the temporal-stability table alone (the error rows take far longer).
  const bool onlyStability = !given.only.empty();
  if (onlyStability && std::string("stability").rfind(given.only, 0) != 0)
    return commandFailed("report --only knows one section, 'stability'; got '" + given.only + "'");
  std::error_code fsError;
  std::filesystem::create_directories(options.out, fsError);
  if (fsError) return commandFailed("cannot create '" + options.out + "': " + fsError.message());

  std::string error;
  HeadlessSession session;
  if (!openHeadlessSession(options, /*debug=*/false, /*benchmarkFloor=*/false, session, error))
    return commandFailed(error);
  report::ReportInfo info;
  info.device = session.context->renderer();
  info.width = options.width;
  info.height = options.height;
  info.quick = given.quick;
  std::vector<report::Row> rows;
  if (!onlyStability) {
    std::fprintf(stderr, "report: rendering the %s preset at %dx%d\n", options.preset.c_str(),
                 options.width, options.height);
    FrameInput input{session.preset.camera, session.preset.sun, options.timeSeconds};
    if (!session.renderer->render(input, error)) return commandFailed(error);
    glFinish();
    if (!measureErrorRows(session, given.quick, rows, info, error)) return commandFailed(error);
  }

  // Temporal stability (issue 19 item 3) on frames of its own size: the traced reference of
  // each frame is what it costs.
  report::StabilityReportSettings stability;
  stability.waterResolution = options.waterResolution;
  stability.references = !given.quick;
  std::vector<report::StabilityRow> stabilityRows;
  std::string stabilityNote;
  if (!report::measureStability(options, stability, stabilityRows, stabilityNote, error))
    return commandFailed(error);

  const std::string dir = options.out + "/";
  if (!onlyStability &&
      (!report::writeCsv(dir + "error_vs_time.csv", rows, error) ||
       !report::writeErrorPlot(dir + "error_vs_time.png", "error against GPU time, " + info.device,
                               rows, error) ||
       !report::writeMarkdown(dir + "error_vs_time.md", info, rows, "error_vs_time.png", error)))
    return commandFailed(error);
  if (!report::writeStabilityTables(dir, info.device, stability, stabilityRows, stabilityNote,
                                    error))
    return commandFailed(error);
  if (!onlyStability)
    std::fprintf(stderr, "report: wrote %serror_vs_time.{csv,md,png} (%zu rows)\n", dir.c_str(),
                 rows.size());
  std::fprintf(stderr, "report: wrote %stemporal_stability.{csv,md} (%zu rows)\n", dir.c_str(),
               stabilityRows.size());
  return 0;
}

}  // namespace ocean
