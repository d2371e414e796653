#include "slope_comparison.h"
#include <postfx/testing.h>

#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <seabed_reference.h>
#include <water_readback.h>

#include "plane_gbuffer.h"
#include "sloped_plane.h"

namespace ocean::validation {
namespace {

// The host's sun elevation at the +x azimuth: planes tilted about z then face it or turn away.
glm::dvec3 sunAlongX(const glm::dvec3& towardSun) {
  const glm::dvec3 sun = glm::normalize(towardSun);
  return {std::hypot(sun.x, sun.z), sun.y, 0.0};
}

// One context of `features` (plus raw output) on `frame`: timed, read back, binned, compared.
bool runVariant(const postfx::FrameDesc& frame, postfx::Feature features, const SlopedPlane& plane,
                double scale, const std::vector<double>& truth, int timedFrames, SlopeLookup& out,
                std::string& error) {
  postfx::CreateDesc create;
  create.features = features | postfx::Feature::Caustics | postfx::testing::RawCausticOutput;
  create.depthConvention = postfx::DepthConvention::ReverseZ;
  create.normalEncoding = postfx::NormalEncoding::WorldXyz;
  const ReportTarget target(plane.desc.width, plane.desc.height);
  if (!runPass(create, frame, postfx::Pass::Caustics, target, timedFrames, out.run, error))
    return false;
  // The pre-passes are part of the method's cost (as in the flat rows); 0 for one that did not
  // run (the physical window runs both: the tile irradiance continues it).
  out.run.medianMs += out.run.stats.pass(postfx::Pass::WavefrontAreaRatio).medianMs +
                      out.run.stats.pass(postfx::Pass::TileIrradiance).medianMs;
  out.run.estimatedMs[static_cast<int>(postfx::Pass::Caustics)] +=
      out.run.estimated(postfx::Pass::WavefrontAreaRatio) +
      out.run.estimated(postfx::Pass::TileIrradiance);
  out.binned = plane.binned(out.run.raw, scale);
  out.stats = compareWithReference(out.binned, truth);
  return true;
}

}  // namespace

bool measureSlope(const postfx::FrameDesc& hostFrame, const SlopeSettings& settings,
                  double slopeDegrees, const std::vector<int>& facings,
                  std::vector<SlopeCase>& cases, std::string& error) {
  postfx::FrameDesc frame = hostFrame;
  const double level = frame.water.level;
  frame.sun.direction = sunAlongX(hostFrame.sun.direction);
  frame.caustics = settings.caustics;
  // The along-light and tri-planar rows are the ray-deviation model's two lookups.
  frame.caustics.model = postfx::CausticsModel::RayDeviation;
  frame.caustics.surfaceFadeDepth = 0.0f;  // the reference has no fade
  frame.godRays.enabled = false;
  frame.objectCaustics = {};
  const glm::dvec3 towardLight =
      -ocean::reference::refractSunRay(frame.sun.direction, 0.0, 0.0, frame.water.ior);

  ocean::reference::WaterTextureSurface surface;
  if (!surface.read(hostFrame.water, error)) return false;
  std::vector<SlopedPlane> planes;
  ocean::reference::ReferenceDesc desc;
  desc.towardSun = frame.sun.direction;
  desc.ior = frame.water.ior;
  desc.targetRelativeError = settings.referenceError;
  desc.maxRays = settings.maxRays;
  desc.progress = settings.progress;
  desc.label = "report: sloped seabed reference";
  for (int facing : facings) {
    SlopedPlaneDesc p;
    p.width = settings.width;
    p.height = settings.height;
    p.binPixels = settings.binPixels;
    p.slopeDegrees = slopeDegrees;
    p.facing = facing;
    p.centre = {hostFrame.camera.position.x, level - settings.receiverDepth,
                hostFrame.camera.position.z};
    p.viewDistance = settings.viewDistance;
    planes.push_back(slopedPlane(p, level));
    const SlopedPlane& plane = planes.back();
    // Crests must stay above the plane everywhere in view (the reference drops a ray whose
    // surface point is under its receiver; the plugin draws nothing above the level).
    if (!(plane.minDepth > surface.maxHeight() + 0.1)) {
      char text[160];
      std::snprintf(text, sizeof(text),
                    "sloped caustics: the %.0f degree plane rises to %.2f m under the level, "
                    "within the waves' %.2f m",
                    slopeDegrees, plane.minDepth, surface.maxHeight());
      error = text;
      return false;
    }
    desc.bins = plane.bins;  // the same for every facing
    desc.receivers.push_back(plane.receiver(level));
  }
  const ocean::reference::ReferenceResult reference =
      ocean::reference::traceSeabedCaustics(surface, desc);

  for (size_t k = 0; k < planes.size(); ++k) {
    const SlopedPlane& plane = planes[k];
    const ocean::reference::ReceiverResult& traced = reference.receivers[k];
    SlopeCase c;
    c.slopeDegrees = slopeDegrees;
    c.facing = plane.desc.facing;
    c.normalDotLight = glm::dot(plane.normal, towardLight);
    c.flatWater = plane.flatWaterFlux(towardLight);
    c.reference = traced.irradiance;
    c.referenceSigma.resize(c.reference.size());
    double sigmaSquares = 0.0, referenceSquares = 0.0;
    for (size_t i = 0; i < c.reference.size(); ++i) {
      c.referenceSigma[i] = traced.relativeError[i] * c.reference[i];
      sigmaSquares += c.referenceSigma[i] * c.referenceSigma[i];
      referenceSquares += c.reference[i] * c.reference[i];
    }
    c.referenceNoise = referenceSquares > 0.0 ? std::sqrt(sigmaSquares / referenceSquares) : 0.0;
    c.referenceMedianError = traced.medianRelativeError;
    c.referenceConverged = reference.converged;
    c.referenceRays = reference.rays;
    c.uniform =
        compareWithReference(std::vector<double>(c.reference.size(), c.flatWater), c.reference);

    const PlaneGbuffer gbuffer(plane.desc.width, plane.desc.height, plane.view);
    postfx::FrameDesc view = frame;
    view.depth = {gbuffer.depth(), GL_DEPTH_COMPONENT32F};
    view.normal = {gbuffer.normal(), GL_RGBA16F};
    view.albedo = {gbuffer.albedo(), GL_RGBA8};
    view.camera.position = plane.camera;
    view.camera.view = glm::mat4(plane.view.view);
    view.camera.projection = plane.view.projection;
    const double scale = 1.0 / (towardLight.y * plane.normal.y);
    if (settings.progress)
      std::fprintf(stderr, "report: sloped caustics, %.0f degrees facing %s: both lookups\n",
                   slopeDegrees, c.facing > 0 ? "the sun" : "away");
    const postfx::Feature none = static_cast<postfx::Feature>(0);
    if (!runVariant(view, none, plane, scale, c.reference, settings.timedFrames, c.alongLight,
                    error) ||
        !runVariant(view, postfx::Feature::TriplanarWalls, plane, scale, c.reference,
                    settings.timedFrames, c.triplanar, error))
      return false;
    if (settings.physicalGrid > 0) {
      postfx::FrameDesc physical = view;
      physical.caustics.model = postfx::CausticsModel::WavefrontAreaRatio;
      physical.caustics.gridResolution = settings.physicalGrid;
      // The window (centred on the camera) holds the whole view inside its fade band (the
      // inner 75 %): the view reaches viewDistance (the camera's offset from the centre, at
      // most) plus half its width, and the layers reach below the plane's deepest bin.
      const double reach =
          plane.desc.viewDistance * (1.0 + std::max(plane.view.aspect, 1.0) / plane.view.focal);
      physical.caustics.windowSize = float(reach / 0.375);
      physical.caustics.maxReceiverDepth = float(plane.maxDepth + 1.0);
      if (!runVariant(physical, postfx::Feature::WavefrontAreaRatio, plane, scale, c.reference,
                      settings.timedFrames, c.physical, error))
        return false;
    }
    c.differenceNoise =
        affineRmseDifferenceNoise(c.alongLight.binned, c.alongLight.stats, c.triplanar.binned,
                                  c.triplanar.stats, c.reference, c.referenceSigma);
    cases.push_back(std::move(c));
  }
  return true;
}

}  // namespace ocean::validation
