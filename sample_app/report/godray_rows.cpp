#include "godray_rows.h"
#include <postfx/testing.h>

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

}  // namespace

bool measureGodRays(const postfx::CreateDesc& host, const postfx::FrameDesc& hostFrame,
                    const ReportTarget& target, const GodRayReportSettings& settings,
                    std::vector<Row>& rows, std::string& note, std::string& error) {
  postfx::CreateDesc create = host;
  create.features = postfx::Feature::GodRays;
  if (postfx::hasFeature(host.features, postfx::Feature::ShadowMask))
    create.features = create.features | postfx::Feature::ShadowMask;
  postfx::FrameDesc frame = hostFrame;
  frame.caustics.enabled = false;
  frame.godRays.enabled = true;

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
  const double convergence = compareWithReference(half, dense).relativeRmse;
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
      PassRun run;
      if (!runPass(create, frame, postfx::Pass::GodRays, target, settings.timedFrames, run, error,
                   variant.sampling))
        return false;
      const ErrorStats stats = compareWithReference(flatten(run.image), dense);
      Row row;
      row.pass = "god_rays";
      row.method = variant.method;
      row.setting = std::to_string(samples) + " samples";
      row.medianMs = run.medianMs;
      row.floorMs = run.floorMs;
      row.relativeRmse = stats.relativeRmse;
      row.correlation = stats.correlation;
      rows.push_back(row);
    }
  }
  return true;
}

}  // namespace ocean::report
