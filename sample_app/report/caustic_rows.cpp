#include "caustic_rows.h"

#include <epoxy/gl.h>

#include <cmath>
#include <cstdio>

#include <seabed_reference.h>
#include <water_readback.h>

#include "error_metrics.h"
#include "flat_gbuffer.h"
#include "pass_runner.h"

namespace ocean::report {
namespace {

// Refracted sun's cosine to the vertical: N.L of a floor facing up, which the raw factor holds.
double refractedCosine(const glm::dvec3& towardSun, double ior) {
  const glm::dvec3 sun = glm::normalize(towardSun);
  const double sinT = std::sqrt(std::max(0.0, 1.0 - sun.y * sun.y)) / ior;
  return std::sqrt(std::max(0.0, 1.0 - sinT * sinT));
}

}  // namespace

bool measureCaustics(const postfx::FrameDesc& hostFrame, const CausticReportSettings& settings,
                     std::vector<Row>& rows, std::string& note, std::string& error) {
  const int w = settings.width, h = settings.height, bin = settings.binPixels;
  const double height = settings.receiverDepth - settings.cameraDepth;  // camera to floor (m)
  const PlaneView topDown = topDownView(w, h, height);
  const double aspect = topDown.aspect, f = topDown.focal;

  postfx::FrameDesc frame = hostFrame;
  const double level = frame.water.level;
  const glm::dvec3 camera(hostFrame.camera.position.x, level - settings.cameraDepth,
                          hostFrame.camera.position.z);
  PlaneGbuffer gbuffer(w, h, topDown.windowDepth);
  ReportTarget target(w, h);
  frame.depth = {gbuffer.depth(), GL_DEPTH_COMPONENT32F};
  frame.normal = {gbuffer.normal(), GL_RGBA16F};
  frame.albedo = {gbuffer.albedo(), GL_RGBA8};
  frame.camera.position = camera;
  frame.camera.view = glm::mat4(topDown.view);
  frame.camera.projection = topDown.projection;
  frame.caustics = postfx::CausticsSettings{};
  frame.caustics.surfaceFadeDepth = 0.0f;  // the reference has no fade
  frame.godRays.enabled = false;
  frame.objectCaustics = {};

  // Bins: blocks of bin x bin pixels; pixel (i, j) sees world x = camera.x + (2(i+.5)/w - 1)
  // * height * aspect / f and z = camera.z - (2(j+.5)/h - 1) * height / f.
  const double pixelX = 2.0 * height * aspect / f / w, pixelZ = 2.0 * height / f / h;
  ocean::reference::ReferenceDesc desc;
  desc.towardSun = glm::normalize(hostFrame.sun.direction);
  desc.ior = hostFrame.water.ior;
  desc.bins.origin = {camera.x - 0.5 * w * pixelX, camera.z - 0.5 * h * pixelZ};
  desc.bins.binSize = bin * pixelX;
  desc.bins.binSizeZ = bin * pixelZ;
  desc.bins.countX = w / bin;
  desc.bins.countZ = h / bin;
  desc.receivers = {ocean::reference::Receiver::flat(settings.receiverDepth)};
  desc.targetRelativeError = settings.referenceError;
  desc.label = "report: seabed reference";
  ocean::reference::WaterTextureSurface surface;
  if (!surface.read(hostFrame.water, error)) return false;
  // The reference sees world coordinates; the water origin is part of the surface.
  const ocean::reference::ReferenceResult reference =
      ocean::reference::traceSeabedCaustics(surface, desc);
  const std::vector<double>& truth = reference.receivers[0].irradiance;
  char text[320];
  std::snprintf(text, sizeof(text),
                "Caustics: flat seabed %.1f m below the level seen from above, %d x %d bins of "
                "%.2f x %.2f m; reference: %.3g rays traced through the GPU's water texture "
                "(level 0) in double, median per-bin error %.2g%s.",
                settings.receiverDepth, desc.bins.countX, desc.bins.countZ, desc.bins.binSize,
                desc.bins.binSizeZ, double(reference.rays),
                reference.receivers[0].medianRelativeError,
                reference.converged ? "" : " (ray cap reached)");
  note = text;

  const double cosine = refractedCosine(desc.towardSun, desc.ior);
  // Pixel (i, j) -> bin (i / bin, (h - 1 - j) / bin): z grows toward the image's bottom row.
  auto binned = [&](const std::vector<float>& raw) {
    std::vector<double> sum(truth.size(), 0.0);
    for (int j = 0; j < h; ++j)
      for (int i = 0; i < w; ++i)
        sum[size_t(((h - 1 - j) / bin) * desc.bins.countX + i / bin)] +=
            double(raw[size_t(j * w + i)]) / cosine;
    for (double& s : sum) s /= double(bin * bin);
    return sum;
  };

  struct Variant {
    std::string method, setting;
    postfx::CausticsSettings caustics;
    bool physical;
  };
  std::vector<Variant> variants;
  for (float reflection : {0.0f, 0.25f}) {
    for (float tau : {100.0f, 400.0f, 800.0f, 3200.0f}) {
      Variant v{reflection > 0.0f ? "seed 002, reflection 0.25" : "seed 002, refraction only",
                "tau " + std::to_string(int(tau)), frame.caustics, false};
      v.caustics.tau = tau;
      v.caustics.reflectionWeight = reflection;
      variants.push_back(v);
    }
  }
  for (float cut : {0.0f, 0.3f}) {
    Variant v{"seed 002, cascade cut-off", "cut " + std::to_string(cut).substr(0, 3) + " tau 800",
              frame.caustics, false};
    v.caustics.minCascadeContrast = cut;
    variants.push_back(v);
  }
  for (int grid : settings.physicalGrids) {
    Variant v{"physical (wavefront area ratio)", "grid " + std::to_string(grid), frame.caustics,
              true};
    v.caustics.model = postfx::CausticsModel::WavefrontAreaRatio;
    v.caustics.gridResolution = grid;
    variants.push_back(v);
  }

  postfx::CreateDesc create;
  create.depthConvention = 0;
  create.normalEncoding = 1;
  const std::vector<double> uniform(truth.size(), 1.0);
  const ErrorStats flat = compareWithReference(uniform, truth);
  Row flatRow;
  flatRow.pass = "caustics";
  flatRow.method = "no caustics (uniform light)";
  flatRow.setting = "-";
  flatRow.relativeRmse = flat.relativeRmse;
  flatRow.note = "the error of drawing no caustic pattern at all";
  rows.push_back(flatRow);
  for (size_t k = 0; k < variants.size(); ++k) {
    const Variant& v = variants[k];
    std::fprintf(stderr, "report: caustics %s, %s (%zu/%zu)\n", v.method.c_str(), v.setting.c_str(),
                 k + 1, variants.size());
    create.features = postfx::Feature::Caustics | postfx::Feature::RawCausticOutput;
    if (v.physical) create.features = create.features | postfx::Feature::PhysicalCaustics;
    frame.caustics = v.caustics;
    PassRun run;
    if (!runPass(create, frame, "caustics", target, settings.timedFrames, run, error)) return false;
    Row row;
    row.pass = "caustics";
    row.method = v.method;
    row.setting = v.setting;
    row.medianMs = run.medianMs;
    row.floorMs = run.floorMs;
    if (v.physical) {
      // The irradiance pass is part of the method's cost: add its median from the same run.
      const double irradianceMs = run.medianMsByPass["caustics_irradiance"];
      row.medianMs += irradianceMs;
      char cost[96];
      std::snprintf(cost, sizeof(cost), "incl. irradiance pass %.2f ms", irradianceMs);
      row.note = cost;
    }
    const ErrorStats stats = compareWithReference(binned(run.raw), truth);
    if (v.physical) {
      row.relativeRmse = stats.relativeRmse;
    } else {
      row.affineRmse = stats.affineRmse;  // omega has no absolute scale
    }
    row.correlation = stats.correlation;
    rows.push_back(row);
  }
  return true;
}

}  // namespace ocean::report
