#include "light_caustic_run.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include <object_caustics_scene.h>

#include "pass_runner.h"
#include "plane_gbuffer.h"

namespace ocean::validation {

namespace {
constexpr double kPi = 3.14159265358979323846;
}  // namespace

LightCausticScene pointLightBallLens(bool underWater, int binCount) {
  LightCausticScene scene;
  const double radius = 0.25, s = 2.0;
  const double ior = underWater ? 1.5 / scene.waterIor : 1.5;
  const double f = ior * radius / (2.0 * (ior - 1.0));
  const double image = 1.0 / (1.0 / f - 1.0 / s);
  const double tilt = 30.0 * kPi / 180.0;
  const glm::dvec3 axis(std::sin(tilt), -std::cos(tilt), 0.0);
  scene.sphere.centre = glm::dvec3(0.0) - axis * (0.98 * image);
  scene.sphere.radius = radius;
  scene.sphere.ior = ior;
  scene.sphere.absorption = {0.2, 1.0, 3.0};
  scene.light.position = scene.sphere.centre - axis * s;
  scene.underWater = underWater;
  scene.binCentre = glm::dvec3(0.0);
  scene.binSide = underWater ? 1.2 : 0.3;
  scene.binCount = binCount;
  return scene;
}

LightCausticScene spotConeCut(double softness, int binCount) {
  LightCausticScene scene;
  scene.sphere.centre = {0.0, 0.6, 0.0};
  scene.sphere.radius = 0.25;
  scene.sphere.ior = 1.5;
  scene.light.position = {0.0, 2.6, 0.0};
  scene.light.spot = true;
  const double tilt = 10.0 * kPi / 180.0;
  scene.light.direction = {std::sin(tilt), -std::cos(tilt), 0.0};
  scene.light.coneAngleDegrees = 20.0;
  scene.light.coneSoftness = softness;
  scene.binCentre = {0.0, 0.0, 0.0};
  scene.binSide = 0.8;
  scene.binCount = binCount;
  return scene;
}

reference::ReceiverBins sceneBins(const LightCausticScene& scene) {
  // Top-down view: view x = world x, view y = -world z, pixel row 0 at the bottom (most +z).
  reference::ReceiverBins bins;
  const double h = 0.5 * scene.binSide;
  bins.origin = {scene.binCentre.x - h, scene.planeY, scene.binCentre.z + h};
  bins.axisU = {scene.binSide, 0.0, 0.0};
  bins.axisV = {0.0, 0.0, -scene.binSide};
  bins.size = scene.binCount;
  return bins;
}

namespace {

// The host of both: `sun` lights the sphere with the sun alone (from the sphere toward the
// light), otherwise with the light alone.
bool runOnHost(const LightCausticScene& scene, const postfx::ObjectCausticsSettings& settings,
               int timedFrames, bool sun, LightCausticRun& out, std::string& error) {
  const int n = scene.binCount;
  // 60 degree vertical field of view: the square image spans binSide at this height.
  const double height = 0.5 * scene.binSide / std::tan(glm::radians(30.0));
  const PlaneView topDown = topDownView(n, n, height);
  PlaneGbuffer gbuffer(n, n, topDown);
  const reference::GlMesh mesh = reference::makeSphereMesh(scene.sphere.radius, 160, 80);
  postfx::CasterMaterial glass;
  glass.ior = float(scene.sphere.ior * (scene.underWater ? scene.waterIor : 1.0));
  glass.absorption = glm::vec3(scene.sphere.absorption);
  glm::dmat4 model(1.0);
  model[3] = glm::dvec4(scene.sphere.centre, 1.0);
  const postfx::CasterMesh caster = mesh.caster(model, glass);

  // The light's receivers: the floor seen from the light over the bins, with room around them.
  const reference::LocalLightSource& source = scene.light;
  const glm::dvec3 toBins = scene.binCentre - source.position;
  double halfAngle = 0.0;
  const reference::ReceiverBins bins = sceneBins(scene);
  for (int c = 0; c < 4; ++c) {
    const glm::dvec3 corner =
        reference::binPoint(bins, glm::dvec2(c & 1, c >> 1) * double(n)) - source.position;
    halfAngle =
        std::max(halfAngle, std::acos(glm::dot(glm::normalize(corner), glm::normalize(toBins))));
  }
  const double fov = std::min(170.0, 2.0 * glm::degrees(halfAngle) * 1.1 + 2.0);
  const reference::LightReceiverMap receivers(source.position, toBins, fov, scene.planeY, 1024);

  postfx::LocalLight light;
  light.type = source.spot ? postfx::LocalLightType::Spot : postfx::LocalLightType::Point;
  light.position = source.position;
  light.direction = source.direction;
  light.intensity = glm::vec3(source.intensity);
  light.range = scene.range;
  light.coneAngleDegrees = float(source.coneAngleDegrees);
  light.coneSoftness = float(source.coneSoftness);
  light.receivers = receivers.desc();

  postfx::CreateDesc create;
  create.features = postfx::Feature::ObjectCaustics;
  create.depthConvention = postfx::DepthConvention::ReverseZ;
  create.normalEncoding = postfx::NormalEncoding::WorldXyz;
  create.maxLocalLights = 1;
  postfx::FrameDesc frame;
  frame.depth = {gbuffer.depth(), GL_DEPTH_COMPONENT32F};
  frame.normal = {gbuffer.normal(), GL_RGBA16F};
  frame.albedo = {gbuffer.albedo(), GL_RGBA8};
  frame.camera.position = {scene.binCentre.x, scene.planeY + height, scene.binCentre.z};
  frame.camera.view = glm::mat4(topDown.view);
  frame.camera.projection = topDown.projection;
  frame.sun.direction = {0.0, 1.0, 0.0};
  frame.water.texture = {};  // no water simulation: the host has glass only
  // Far above everything under water (the light's paths all in it), far below in air.
  frame.water.level = scene.underWater ? scene.planeY + 1000.0 : scene.planeY - 1000.0;
  frame.water.ior = float(scene.waterIor);
  frame.water.absorption = glm::vec3(scene.waterAbsorption);
  // The light along the view ray is the host's to attenuate: the bins hold what lands.
  frame.viewExtinction = postfx::ViewExtinction::Host;
  frame.caustics.enabled = false;
  frame.godRays.enabled = false;
  frame.objectCaustics.casters = &caster;
  frame.objectCaustics.casterCount = 1;
  frame.objectCaustics.settings = settings;
  frame.objectCaustics.sunCaustics = false;
  frame.objectCaustics.lights = &light;
  frame.objectCaustics.lightCount = 1;
  const glm::dvec3 towardSun = glm::normalize(source.position - scene.sphere.centre);
  std::optional<reference::ReceiverMap> sunReceivers;
  if (sun) {
    sunReceivers.emplace(towardSun, scene.binCentre, scene.binSide, scene.planeY, 1024);
    frame.sun.direction = towardSun;
    frame.objectCaustics.sunCaustics = true;
    frame.objectCaustics.receivers = sunReceivers->desc();
    frame.objectCaustics.lightCount = 0;
  }

  const ReportTarget target(n, n);
  if (timedFrames <= 0) {  // the image alone: one dispatch, no floor, no timing
    postfx::Context* context = nullptr;
    if (postfx::create(create, context) != postfx::Result::Ok) {
      error = std::string("postfx: ") + postfx::lastError(nullptr);
      return false;
    }
    frame.target = {target.texture(), GL_RGBA32F};
    const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    glClearTexImage(target.texture(), 0, GL_RGBA, GL_FLOAT, zero);
    const bool ok = postfx::dispatch(*context, frame) == postfx::Result::Ok;
    if (!ok) error = std::string("postfx: ") + postfx::lastError(context);
    out.skip = postfx::stats(*context).lightSkip[0];
    postfx::destroy(context);
    if (!ok) return false;
    std::vector<glm::vec4> image(size_t(n) * n);
    glGetTextureImage(target.texture(), 0, GL_RGBA, GL_FLOAT,
                      GLsizei(image.size() * sizeof(glm::vec4)), image.data());
    out.irradiance.resize(image.size());
    for (size_t i = 0; i < image.size(); ++i) out.irradiance[i] = glm::dvec3(glm::vec3(image[i]));
    return true;
  }
  PassRun run;
  if (!runPass(create, frame, postfx::Pass::ObjectCaustics, target, timedFrames, run, error))
    return false;
  out.medianMs = sun ? run.medianMs : run.stats.objectLight(0).medianMs;
  out.estimatedMs = run.estimated(postfx::Pass::ObjectCaustics);
  out.floorMs = run.floorMs;
  out.skip = run.stats.lightSkip[0];
  out.irradiance.resize(size_t(n) * n);
  for (size_t i = 0; i < out.irradiance.size(); ++i)
    out.irradiance[i] = glm::dvec3(glm::vec3(run.image[i]));
  return true;
}

}  // namespace

bool runLightCaustic(const LightCausticScene& scene, const postfx::ObjectCausticsSettings& settings,
                     int timedFrames, LightCausticRun& out, std::string& error) {
  return runOnHost(scene, settings, timedFrames, false, out, error);
}

bool timeSunCaustic(const LightCausticScene& scene, const postfx::ObjectCausticsSettings& settings,
                    int timedFrames, double& ms, double& floorMs, std::string& error) {
  LightCausticRun run;
  if (!runOnHost(scene, settings, std::max(timedFrames, 1), true, run, error)) return false;
  ms = run.medianMs;
  floorMs = run.floorMs;
  return true;
}

}  // namespace ocean::validation
