#include "godray_rows.h"
#include <postfx/testing.h>

#include <algorithm>
#include <cstdio>
#include <iterator>

#include <godray_reference.h>

#include "error_metrics.h"

namespace ocean::report {
namespace {

std::vector<double> flatten(const std::vector<glm::vec4>& image) {
  std::vector<double> out;
  out.reserve(image.size() * 3);
  for (const glm::vec4& p : image)
    for (int c = 0; c < 3; ++c) out.push_back(double(p[c]));
  return out;
}

std::vector<double> flatten(const std::vector<glm::dvec3>& image) {
  std::vector<double> out;
  out.reserve(image.size() * 3);
  for (const glm::dvec3& p : image)
    for (int c = 0; c < 3; ++c) out.push_back(p[c]);
  return out;
}

// The dense march of the god rays as the plugin computes them for `frame` (its caustics model's
// light field, full resolution): the mean of `phases` frames of 64 samples spread uniformly along
// each ray, each frame's samples shifted by 1 / phases of a step.
bool denseFieldMarch(const postfx::CreateDesc& create, postfx::FrameDesc frame,
                     const validation::ReportTarget& target, int phases, std::vector<double>& out,
                     std::string& error) {
  postfx::Context* context = nullptr;
  if (postfx::create(create, context) != postfx::Result::Ok) {
    error = std::string("postfx: ") + postfx::lastError(nullptr);
    return false;
  }
  postfx::testing::setGodRaySampling(*context, postfx::testing::GodRaySampling::UniformAlongRay);
  frame.target = {target.texture(), GL_RGBA32F};
  frame.godRays.resolution = postfx::GodRayResolution::Full;
  frame.godRays.sampleCount = 64;
  frame.godRays.dither = false;
  const size_t pixels = size_t(target.width()) * size_t(target.height());
  std::vector<glm::vec4> image(pixels);
  out.assign(pixels * 3, 0.0);
  const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  bool ok = true;
  for (int k = 0; k < phases && ok; ++k) {
    postfx::testing::setGodRayUniformPhase(*context, (float(k) + 0.5f) / float(phases));
    glClearTexImage(target.texture(), 0, GL_RGBA, GL_FLOAT, zero);
    ok = postfx::dispatch(*context, frame) == postfx::Result::Ok;
    if (!ok) break;
    glGetTextureImage(target.texture(), 0, GL_RGBA, GL_FLOAT, GLsizei(pixels * sizeof(glm::vec4)),
                      image.data());
    for (size_t i = 0; i < pixels; ++i)
      for (int c = 0; c < 3; ++c) out[i * 3 + c] += double(image[i][c]) / phases;
  }
  if (!ok) error = std::string("postfx: ") + postfx::lastError(context);
  postfx::destroy(context);
  return ok;
}

// One report row: a god-ray march's time and its error against the dense march.
Row godRayRow(const char* method, int samples, const validation::PassRun& run,
              const std::vector<double>& dense) {
  const validation::ErrorStats stats = validation::compareWithReference(flatten(run.image), dense);
  Row row;
  row.pass = "god_rays";
  row.method = method;
  row.setting = std::to_string(samples) + " samples";
  row.medianMs = run.medianMs;
  row.estimatedMs = run.estimated(postfx::Pass::GodRays);
  row.floorMs = run.floorMs;
  row.relativeRmse = stats.relativeRmse;
  row.correlation = stats.correlation;
  return row;
}

// Rows for the god rays of the TileIrradiance model (their light the seabed caustics' field),
// against that model's dense march.
bool measureFieldGodRays(const postfx::CreateDesc& create, postfx::FrameDesc frame,
                         const validation::ReportTarget& target,
                         const GodRayReportSettings& settings, std::vector<Row>& rows,
                         std::string& note, std::string& error) {
  frame.caustics.model = postfx::CausticsModel::TileIrradiance;
  const int phases = std::max(settings.referenceSamples / 64, 2);
  std::fprintf(stderr, "report: god rays from the tile field, dense march (%d and %d samples)\n",
               64 * phases / 2, 64 * phases);
  std::vector<double> dense, half;
  if (!denseFieldMarch(create, frame, target, phases, dense, error) ||
      !denseFieldMarch(create, frame, target, phases / 2, half, error))
    return false;
  char text[256];
  std::snprintf(text, sizeof(text),
                " God rays from the tile field: the plugin's own march of that field at full "
                "resolution with %d uniform samples per pixel; %d vs %d differ by %.2g relative "
                "RMSE.",
                64 * phases, 64 * phases / 2, 64 * phases,
                validation::compareWithReference(half, dense).relativeRmse);
  note += text;
  struct Variant {
    const char* method;
    postfx::GodRayResolution resolution;
  };
  using postfx::GodRayResolution;
  const Variant variants[] = {
      {"god rays, tile field, world grid", GodRayResolution::Full},
      {"god rays, tile field, world grid, half res", GodRayResolution::Half},
      {"god rays, tile field, world grid, quarter res", GodRayResolution::Quarter},
  };
  const int counts[] = {8, 16, 32};
  for (const Variant& variant : variants) {
    for (int samples : counts) {
      std::fprintf(stderr, "report: %s, %d samples\n", variant.method, samples);
      frame.godRays.sampleCount = samples;
      frame.godRays.resolution = variant.resolution;
      validation::PassRun run;
      if (!validation::runPass(create, frame, postfx::Pass::GodRays, target, settings.timedFrames,
                               run, error))
        return false;
      rows.push_back(godRayRow(variant.method, samples, run, dense));
    }
  }
  return true;
}

}  // namespace

bool measureGodRays(const postfx::CreateDesc& host, const postfx::FrameDesc& hostFrame,
                    const validation::ReportTarget& target, const GodRayReportSettings& settings,
                    std::vector<Row>& rows, std::string& note, std::string& error) {
  postfx::CreateDesc create = host;
  create.features = postfx::Feature::GodRays;
  if (postfx::hasFeature(host.features, postfx::Feature::ShadowMask))
    create.features = create.features | postfx::Feature::ShadowMask;
  postfx::FrameDesc frame = hostFrame;
  frame.caustics.enabled = false;
  frame.godRays.enabled = true;
  // The double-precision reference marches ray deviation's factor: the RayDeviation model's god
  // rays.
  frame.caustics.model = postfx::CausticsModel::RayDeviation;

  std::fprintf(stderr, "report: god-ray reference, %d and %d samples per pixel\n",
               settings.referenceSamples / 2, settings.referenceSamples);
  ocean::reference::GodRayInputs inputs;
  if (!ocean::reference::captureGodRayInputs(create, frame, inputs, error)) return false;
  ocean::reference::GodRayReferenceOptions options;
  options.samples = settings.referenceSamples;
  const std::vector<double> dense =
      flatten(ocean::reference::renderGodRayReference(create, frame, inputs, options));
  options.samples = settings.referenceSamples / 2;
  const std::vector<double> half =
      flatten(ocean::reference::renderGodRayReference(create, frame, inputs, options));
  const double convergence = validation::compareWithReference(half, dense).relativeRmse;
  char text[256];
  std::snprintf(text, sizeof(text),
                "God rays: dense march with %d segments per pixel in double (the same model); "
                "%d vs %d segments differ by %.2g relative RMSE.",
                settings.referenceSamples, settings.referenceSamples / 2, settings.referenceSamples,
                convergence);
  note = text;

  struct Variant {
    const char* method;
    postfx::GodRayResolution resolution;
    postfx::testing::GodRaySampling sampling;
  };
  using postfx::GodRayResolution;
  const Variant variants[] = {
      {"god rays, world grid", GodRayResolution::Full, postfx::testing::GodRaySampling::WorldGrid},
      {"god rays, world grid, half res", GodRayResolution::Half,
       postfx::testing::GodRaySampling::WorldGrid},
      {"god rays, world grid, quarter res", GodRayResolution::Quarter,
       postfx::testing::GodRaySampling::WorldGrid},
      {"god rays, uniform along ray", GodRayResolution::Full,
       postfx::testing::GodRaySampling::UniformAlongRay},
  };
  const int counts[] = {4, 8, 16, 32, 64};
  int done = 0;
  for (const Variant& variant : variants) {
    for (int samples : counts) {
      std::fprintf(stderr, "report: %s, %d samples (%d/%zu)\n", variant.method, samples, ++done,
                   std::size(variants) * std::size(counts));
      frame.godRays.sampleCount = samples;
      frame.godRays.resolution = variant.resolution;
      validation::PassRun run;
      if (!validation::runPass(create, frame, postfx::Pass::GodRays, target, settings.timedFrames,
                               run, error, variant.sampling))
        return false;
      rows.push_back(godRayRow(variant.method, samples, run, dense));
    }
  }
  return measureFieldGodRays(create, frame, target, settings, rows, note, error);
}

}  // namespace ocean::report
