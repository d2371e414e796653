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
#include <shader_statistics.h>
#include <slope_rows.h>
#include <source_revision.h>
#include <stability_rows.h>

#include "commands.h"
#include "headless_session.h"
#include "local_water_rows.h"
#include "reflected_rows.h"
#include "volume_rows.h"

namespace ocean {
namespace {

// The error-against-run-time rows, on the frame now in `session`'s G-buffer.
bool measureErrorRows(HeadlessSession& session, bool quick, std::vector<report::Row>& rows,
                      report::ReportInfo& info, std::string& error) {
  const postfx::CreateDesc& host = session.plugin->createDesc();
  const postfx::FrameDesc& frame = session.plugin->lastFrame();
  validation::ReportTarget target(info.width, info.height);
  report::GodRayReportSettings godRays;
  godRays.referenceSamples = quick ? 1024 : 2048;
  godRays.timedFrames = quick ? 6 : 16;
  std::string godRayNote;
  if (!report::measureGodRays(host, frame, target, godRays, rows, godRayNote, error)) return false;
  // The flat seabed at the resolutions users run, 4-pixel bins each (the same 60 degree view, so
  // finer bins at larger sizes); every model at 1280x720, which the plot shows. The trace's
  // median bin error: 2 % at 320x180 (3.2e7 rays, 3 min), 3 % at 640x360, 5 % at 1280x720
  // (57,600 bins): its noise then lowers a pattern correlation of 0.8 by < 0.01.
  std::vector<report::CausticReportSettings> caustics;
  for (const int width : quick ? std::vector<int>{160} : std::vector<int>{320, 640, 1280}) {
    report::CausticReportSettings size;
    size.seabed.width = width;
    size.seabed.height = width == 160 ? 88 : width * 9 / 16;
    size.seabed.binPixels = 4;
    size.seabed.referenceError = quick ? 0.03 : width >= 1280 ? 0.05 : width >= 640 ? 0.03 : 0.02;
    size.timedFrames = godRays.timedFrames;
    size.everyModel = quick || width >= 1280;
    if (quick) size.physicalGrids = {64, 128, 256};
    caustics.push_back(size);
  }
  std::string causticNote;
  if (!report::measureCaustics(frame, caustics, rows, causticNote, error)) return false;
  // Slopes: the default water lookup (along the light) against Feature::TriplanarWalls.
  validation::SlopeSettings slopes;
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
  // --only stability: the temporal-stability table alone; --only local-water / --only
  // reflected: the local water or reflected caustics rows alone, into local_water.{csv,md,png}
  // or reflected.{csv,md,png} (the error rows take far longer).
  auto only = [&given](const char* section) {
    return !given.only.empty() && std::string(section).rfind(given.only, 0) == 0;
  };
  const bool onlyStability = only("stability");
  const bool onlyLocalWater = only("local-water");
  const bool onlyReflected = only("reflected");
  const bool onlyVolume = only("volume");
  if (!given.only.empty() && !onlyStability && !onlyLocalWater && !onlyReflected && !onlyVolume)
    return commandFailed(
        "report --only knows four sections, 'stability', 'local-water', 'reflected' and "
        "'volume'; got '" +
        given.only + "'");
  std::error_code fsError;
  std::filesystem::create_directories(options.out, fsError);
  if (fsError) return commandFailed("cannot create '" + options.out + "': " + fsError.message());

  // Every row is estimated on a GPU class too (docs/gpu_cost.md): the driver's dump of each
  // program's arithmetic must be asked for before the GL context exists.
  cost::requestMesaShaderDump();
  validation::estimateRuns(true);
  std::string error;
  HeadlessSession session;
  if (!openHeadlessSession(options, /*debug=*/false, /*benchmarkFloor=*/false, session, error))
    return commandFailed(error);
  report::ReportInfo info;
  info.device = session.context->renderer();
  info.date = report::utcDate();
  info.revision = report::sourceRevision();
  info.width = options.width;
  info.height = options.height;
  info.quick = given.quick;
  LocalWaterReportSettings localWater;
  if (given.quick) {
    localWater.width = 320;
    localWater.height = 180;
    localWater.grids = {64, 256};
    localWater.timedFrames = 6;
  }
  const std::string dir = options.out + "/";
  std::vector<report::Row> rows;
  // Beside the plot against llvmpipe's time, the same rows against the cost model's estimate.
  auto writeEstimatePlot = [&](const std::string& plot, const std::string& title) {
    return !report::anyEstimated(rows) ||
           report::writeErrorPlot(report::estimatePlotFile(plot),
                                  title + ", ESTIMATED on the RTX 3060 class at 1920x1080", rows,
                                  error, report::PlotBackend::Auto, nullptr,
                                  report::TimeAxis::Estimated);
  };
  // One sweep's rows alone into <name>.{csv,md,png}.
  auto writeSection = [&](const char* name, const std::string& title) {
    const std::string stem = dir + name;
    if (!report::writeCsv(stem + ".csv", info, rows, error) ||
        !report::writeErrorPlot(stem + ".png", title + ", " + info.device, rows, error) ||
        !writeEstimatePlot(stem + ".png", title) ||
        !report::writeMarkdown(stem + ".md", info, rows, std::string(name) + ".png", error))
      return false;
    std::fprintf(stderr, "report: wrote %s.{csv,md,png} (%zu rows)\n", stem.c_str(), rows.size());
    return true;
  };
  if (onlyLocalWater) {
    info.width = localWater.width;
    info.height = localWater.height;
    if (!measureLocalWaterRows(given, localWater, rows, info.referenceNote, error) ||
        !writeSection("local_water", "local water"))
      return commandFailed(error);
    return 0;
  }
  if (onlyReflected) {
    ReflectedReportSettings reflected;
    if (given.quick) {
      reflected.width = 320;
      reflected.height = 180;
      reflected.grids = {128, 512};
      reflected.timedFrames = 6;
    }
    info.width = reflected.width;
    info.height = reflected.height;
    if (!measureReflectedRows(given, reflected, rows, info.referenceNote, error) ||
        !writeSection("reflected", "reflected caustics"))
      return commandFailed(error);
    return 0;
  }
  if (onlyVolume) {
    VolumeReportSettings volume;
    volume.imageDir = options.out;
    if (given.quick) {
      volume.width = 320;
      volume.height = 180;
      volume.grids = {64, 256};
      volume.referenceRaysPerSide = 600;
      volume.timedFrames = 6;
      volume.costWidth = 640;
      volume.costHeight = 360;
    }
    info.width = volume.width;
    info.height = volume.height;
    if (!measureVolumeRows(volume, rows, info.referenceNote, error) ||
        !writeSection("volume", "volume caustics"))
      return commandFailed(error);
    return 0;
  }
  if (!onlyStability) {
    std::fprintf(stderr, "report: rendering the %s preset at %dx%d\n", options.preset.c_str(),
                 options.width, options.height);
    FrameInput input{session.preset.camera, session.preset.sun, options.timeSeconds};
    if (!session.renderer->render(input, error)) return commandFailed(error);
    glFinish();
    if (!measureErrorRows(session, given.quick, rows, info, error)) return commandFailed(error);
    std::string localNote;
    if (!measureLocalWaterRows(given, localWater, rows, localNote, error))
      return commandFailed(error);
    // The sweep's sessions each made their own context current and released it on closing:
    // what follows draws in this command's.
    session.context->makeCurrent();
    info.referenceNote += "\n\n" + localNote;
  }

  // Temporal stability on frames of its own size: the traced reference of
  // each frame is what it costs.
  report::StabilityReportSettings stability;
  stability.waterResolution = options.waterResolution;
  stability.references = !given.quick;
  std::vector<report::StabilityRow> stabilityRows;
  std::string stabilityNote;
  if (!report::measureStability(options, stability, stabilityRows, stabilityNote, error))
    return commandFailed(error);

  if (!onlyStability &&
      (!report::writeCsv(dir + "error_vs_time.csv", info, rows, error) ||
       !report::writeErrorPlot(dir + "error_vs_time.png", "error against GPU time, " + info.device,
                               rows, error) ||
       !writeEstimatePlot(dir + "error_vs_time.png", "error against GPU time") ||
       !report::writeMarkdown(dir + "error_vs_time.md", info, rows, "error_vs_time.png", error)))
    return commandFailed(error);
  if (!report::writeStabilityTables(dir, info, stability, stabilityRows, stabilityNote, error))
    return commandFailed(error);
  if (!onlyStability)
    std::fprintf(stderr, "report: wrote %serror_vs_time.{csv,md,png} (%zu rows)\n", dir.c_str(),
                 rows.size());
  std::fprintf(stderr, "report: wrote %stemporal_stability.{csv,md} (%zu rows)\n", dir.c_str(),
               stabilityRows.size());
  return 0;
}

}  // namespace ocean
