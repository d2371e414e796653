#include "flat_seabed_comparison.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include <water_readback.h>

#include "plane_gbuffer.h"
#include "streak_ratio.h"

namespace ocean::validation {
namespace {

// Refracted sun's cosine to the vertical: N.L of a floor facing up, which the raw factor holds.
double refractedCosine(const glm::dvec3& towardSun, double ior) {
  const glm::dvec3 sun = glm::normalize(towardSun);
  const double sinT = std::sqrt(std::max(0.0, 1.0 - sun.y * sun.y)) / ior;
  return std::sqrt(std::max(0.0, 1.0 - sinT * sinT));
}

}  // namespace

double contrast(const std::vector<double>& values) {
  double sum = 0.0, sumSq = 0.0;
  for (double v : values) sum += v, sumSq += v * v;
  const double n = double(values.size()), mean = sum / n;
  return mean > 0.0 ? std::sqrt(std::max(0.0, sumSq / n - mean * mean)) / mean
                    : std::numeric_limits<double>::quiet_NaN();
}

FlatSeabedComparison::FlatSeabedComparison() = default;
FlatSeabedComparison::~FlatSeabedComparison() = default;

bool FlatSeabedComparison::prepare(const postfx::FrameDesc& hostFrame,
                                   const FlatSeabedSettings& settings, std::string& error) {
  settings_ = settings;
  const int w = settings.width, h = settings.height, bin = settings.binPixels;
  const double height = settings.receiverDepth - settings.cameraDepth;  // camera to floor (m)
  const PlaneView topDown = topDownView(w, h, height);
  const double aspect = topDown.aspect, f = topDown.focal;

  frame_ = hostFrame;
  const double level = frame_.water.level;
  const glm::dvec3 camera(hostFrame.camera.position.x, level - settings.cameraDepth,
                          hostFrame.camera.position.z);
  gbuffer_ = std::make_unique<PlaneGbuffer>(w, h, topDown);
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
  return validation::streakRatio(binned, desc_.bins.countX, desc_.bins.countZ, desc_.bins.binSize,
                                 desc_.bins.binSizeZ, desc_.towardSun);
}

}  // namespace ocean::validation
