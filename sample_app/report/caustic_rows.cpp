#include "caustic_rows.h"
#include <postfx/testing.h>

#include <epoxy/gl.h>

#include <cmath>
#include <cstdio>
#include <optional>

#include <seabed_reference.h>
#include <water_readback.h>

#include "error_metrics.h"
#include "flat_gbuffer.h"
#include "pass_runner.h"
#include "streak_ratio.h"

namespace ocean::report {
namespace {

// Refracted sun's cosine to the vertical: N.L of a floor facing up, which the raw factor holds.
double refractedCosine(const glm::dvec3& towardSun, double ior) {
  const glm::dvec3 sun = glm::normalize(towardSun);
  const double sinT = std::sqrt(std::max(0.0, 1.0 - sun.y * sun.y)) / ior;
  return std::sqrt(std::max(0.0, 1.0 - sinT * sinT));
}

}  // namespace

FlatSeabedComparison::FlatSeabedComparison() = default;
FlatSeabedComparison::~FlatSeabedComparison() = default;

bool FlatSeabedComparison::prepare(const postfx::FrameDesc& hostFrame,
                                   const CausticReportSettings& settings, std::string& error) {
  settings_ = settings;
  const int w = settings.width, h = settings.height, bin = settings.binPixels;
  const double height = settings.receiverDepth - settings.cameraDepth;  // camera to floor (m)
  const PlaneView topDown = topDownView(w, h, height);
  const double aspect = topDown.aspect, f = topDown.focal;

  frame_ = hostFrame;
  const double level = frame_.water.level;
  const glm::dvec3 camera(hostFrame.camera.position.x, level - settings.cameraDepth,
                          hostFrame.camera.position.z);
  gbuffer_ = std::make_unique<PlaneGbuffer>(w, h, topDown.windowDepth);
  target_ = std::make_unique<ReportTarget>(w, h);
  frame_.depth = {gbuffer_->depth(), GL_DEPTH_COMPONENT32F};
  frame_.normal = {gbuffer_->normal(), GL_RGBA16F};
  frame_.albedo = {gbuffer_->albedo(), GL_RGBA8};
  frame_.camera.position = camera;
  frame_.camera.view = glm::mat4(topDown.view);
  frame_.camera.projection = topDown.projection;
  frame_.godRays.enabled = false;
  frame_.objectCaustics = {};

  // Bins: blocks of bin x bin pixels; pixel (i, j) sees world x = camera.x + (2(i+.5)/w - 1)
  // * height * aspect / f and z = camera.z - (2(j+.5)/h - 1) * height / f.
  const double pixelX = 2.0 * height * aspect / f / w, pixelZ = 2.0 * height / f / h;
  desc_ = {};
  desc_.towardSun = glm::normalize(hostFrame.sun.direction);
  desc_.ior = hostFrame.water.ior;
  desc_.sunAngularRadius = 0.5 * glm::radians(double(hostFrame.sun.angularDiameterDegrees));
  desc_.bins.origin = {camera.x - 0.5 * w * pixelX, camera.z - 0.5 * h * pixelZ};
  desc_.bins.binSize = bin * pixelX;
  desc_.bins.binSizeZ = bin * pixelZ;
  desc_.bins.countX = w / bin;
  desc_.bins.countZ = h / bin;
  desc_.receivers = {ocean::reference::Receiver::flat(settings.receiverDepth)};
  desc_.targetRelativeError = settings.referenceError;
  desc_.label = "report: seabed reference";
  ocean::reference::WaterTextureSurface surface;
  if (!surface.read(hostFrame.water, error)) return false;
  // The reference sees world coordinates; the water origin is part of the surface.
  reference_ = ocean::reference::traceSeabedCaustics(surface, desc_);
  cosine_ = refractedCosine(desc_.towardSun, desc_.ior);
  return true;
}

// Pixel (i, j) -> bin (i / bin, (h - 1 - j) / bin): z grows toward the image's bottom row.
std::vector<double> FlatSeabedComparison::binRaw(const std::vector<float>& raw) const {
  const int w = settings_.width, h = settings_.height, bin = settings_.binPixels;
  std::vector<double> sum(truth().size(), 0.0);
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i)
      sum[size_t(((h - 1 - j) / bin) * desc_.bins.countX + i / bin)] +=
          double(raw[size_t(j * w + i)]) / cosine_;
  for (double& s : sum) s /= double(bin * bin);
  return sum;
}

bool FlatSeabedComparison::run(postfx::CreateDesc create, const postfx::CausticsSettings& caustics,
                               int timedFrames, PassRun& out, std::vector<double>& binned,
                               std::string& error) const {
  create.features = create.features | postfx::Feature::Caustics | postfx::testing::RawCausticOutput;
  create.depthConvention = postfx::DepthConvention::ReverseZ;
  create.normalEncoding = postfx::NormalEncoding::WorldXyz;
  postfx::FrameDesc frame = frame_;
  frame.caustics = caustics;
  frame.caustics.surfaceFadeDepth = 0.0f;  // the reference has no fade
  if (!runPass(create, frame, postfx::Pass::Caustics, *target_, timedFrames, out, error))
    return false;
  binned = binRaw(out.raw);
  return true;
}

double FlatSeabedComparison::streakRatio(const std::vector<double>& binned) const {
  return ocean::report::streakRatio(binned, desc_.bins.countX, desc_.bins.countZ,
                                    desc_.bins.binSize, desc_.bins.binSizeZ, desc_.towardSun);
}

bool measureCaustics(const postfx::FrameDesc& hostFrame, const CausticReportSettings& settings,
                     std::vector<Row>& rows, std::string& note, std::string& error) {
  FlatSeabedComparison seabed;
  if (!seabed.prepare(hostFrame, settings, error)) return false;
  const ocean::reference::ReferenceResult& reference = seabed.reference();
  const ocean::reference::ReferenceDesc& desc = seabed.desc();
  const std::vector<double>& truth = seabed.truth();
  const double truthStreaks = seabed.streakRatio(truth);
  char text[400];
  std::snprintf(text, sizeof(text),
                "Caustics: flat seabed %.1f m below the level seen from above, %d x %d bins of "
                "%.2f x %.2f m; reference: %.3g rays traced through the GPU's water texture "
                "(level 0) in double, median per-bin error %.2g%s; its streak ratio (gradient "
                "energy across / along the sun's azimuth) %.2f.",
                settings.receiverDepth, desc.bins.countX, desc.bins.countZ, desc.bins.binSize,
                desc.bins.binSizeZ, double(reference.rays),
                reference.receivers[0].medianRelativeError,
                reference.converged ? "" : " (ray cap reached)", truthStreaks);
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
              PrePass{postfx::Pass::CausticsTileIrradiance, "tile pre-pass"}};
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
    Variant v{"ray deviation, cascade cut-off",
              "cut " + std::to_string(cut).substr(0, 3) + " tau 800", rayDeviation, false,
              std::nullopt};
    v.caustics.minCascadeContrast = cut;
    variants.push_back(v);
  }
  for (int grid : settings.physicalGrids) {
    Variant v{"physical (wavefront area ratio)", "grid " + std::to_string(grid),
              postfx::CausticsSettings{}, true,
              PrePass{postfx::Pass::CausticsIrradiance, "irradiance pass"}};
    v.caustics.model = postfx::CausticsModel::WavefrontAreaRatio;
    v.caustics.gridResolution = grid;
    variants.push_back(v);
  }

  const std::vector<double> uniform(truth.size(), 1.0);
  const ErrorStats flat = compareWithReference(uniform, truth);
  Row flatRow;
  flatRow.pass = "caustics";
  flatRow.method = "no caustics (uniform light)";
  flatRow.setting = "-";
  flatRow.relativeRmse = flat.relativeRmse;
  flatRow.affineRmse = flat.affineRmse;
  flatRow.note = "the error of drawing no caustic pattern at all";
  rows.push_back(flatRow);
  for (size_t k = 0; k < variants.size(); ++k) {
    const Variant& v = variants[k];
    std::fprintf(stderr, "report: caustics %s, %s (%zu/%zu)\n", v.method.c_str(), v.setting.c_str(),
                 k + 1, variants.size());
    postfx::CreateDesc create;
    create.features = v.physical ? postfx::Feature::PhysicalCaustics : postfx::Feature::None;
    PassRun run;
    std::vector<double> binned;
    if (!seabed.run(create, v.caustics, settings.timedFrames, run, binned, error)) return false;
    Row row;
    row.pass = "caustics";
    row.method = v.method;
    row.setting = v.setting;
    row.medianMs = run.medianMs;
    row.floorMs = run.floorMs;
    if (v.prePass) {
      const double prePassMs = run.stats.pass(v.prePass->pass).medianMs;
      row.medianMs += prePassMs;
      char cost[160];
      std::snprintf(cost, sizeof(cost), "incl. %s %.2f ms; ", v.prePass->label, prePassMs);
      row.note = cost;
      // The physical window is continued by the tile irradiance: its pre-pass runs too.
      const postfx::PassStats& tile = run.stats.pass(postfx::Pass::CausticsTileIrradiance);
      if (v.prePass->pass != postfx::Pass::CausticsTileIrradiance && !tile.skipped) {
        row.medianMs += tile.medianMs;
        std::snprintf(cost, sizeof(cost), "incl. tile pre-pass %.2f ms; ", tile.medianMs);
        row.note += cost;
      }
    }
    char streaks[96];
    std::snprintf(streaks, sizeof(streaks), "streak ratio %.2f (traced %.2f)",
                  seabed.streakRatio(binned), truthStreaks);
    row.note += streaks;
    const ErrorStats stats = compareWithReference(binned, truth);
    // Ray deviation's omega has no absolute scale; the irradiance models' does.
    if (v.prePass) row.relativeRmse = stats.relativeRmse;
    // Every model's pattern error too: the plot's seabed panel compares them all on it.
    row.affineRmse = stats.affineRmse;
    row.correlation = stats.correlation;
    rows.push_back(row);
  }
  return true;
}

}  // namespace ocean::report
