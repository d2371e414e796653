#include "volume_caustic_run.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>
#include <deque>

#include <godray_reference.h>
#include <object_caustics_scene.h>
#include <volume_caustics_reference.h>

#include "pass_runner.h"
#include "plane_gbuffer.h"

namespace ocean::validation {
namespace {

constexpr double kPi = 3.14159265358979323846;

PlaneView wallView(const VolumeCausticScene& scene) {
  return planeView(scene.width, scene.height, scene.wallDistance, glm::dvec3(0.0, 0.0, 1.0),
                   glm::dvec3(0.0, 1.0, 0.0));
}

glm::dvec3 refractedSun(const VolumeCausticScene& scene) {
  const glm::dvec3 i = -glm::normalize(scene.towardSun);
  const double eta = 1.0 / scene.waterIor, c = i.y * -1.0;
  const double k = 1.0 - eta * eta * (1.0 - c * c);
  return glm::normalize(eta * i + (eta * c - std::sqrt(std::max(k, 0.0))) * glm::dvec3(0, 1, 0));
}

std::vector<glm::dvec3> readLight(GLuint texture, int width, int height) {
  std::vector<glm::vec4> image(size_t(width) * size_t(height));
  glGetTextureImage(texture, 0, GL_RGBA, GL_FLOAT, GLsizei(image.size() * sizeof(glm::vec4)),
                    image.data());
  std::vector<glm::dvec3> out(image.size());
  for (size_t i = 0; i < image.size(); ++i) out[i] = glm::dvec3(glm::vec3(image[i]));
  return out;
}

}  // namespace

VolumeCausticScene glassSphereInWater(int width, int height) {
  VolumeCausticScene scene;
  scene.sphere.centre = {0.0, 0.5, -5.0};
  scene.sphere.radius = 0.5;
  scene.sphere.ior = 1.5 / scene.waterIor;
  const double zenith = 25.0 * kPi / 180.0;
  scene.towardSun = {std::sin(zenith), std::cos(zenith), 0.0};
  scene.width = width;
  scene.height = height;
  return scene;
}

bool runVolumeCaustic(const VolumeCausticScene& scene,
                      const postfx::ObjectCausticsSettings& settings,
                      const VolumeCausticOptions& options, VolumeCausticRun& out,
                      std::string& error) {
  const PlaneView view = wallView(scene);
  PlaneGbuffer gbuffer(scene.width, scene.height, view);
  const reference::GlMesh mesh = reference::makeSphereMesh(scene.sphere.radius, 160, 80);
  postfx::CasterMaterial glass;
  glass.ior = float(scene.sphere.ior * scene.waterIor);
  glass.absorption = glm::vec3(scene.sphere.absorption);
  glm::dmat4 model(1.0);
  model[3] = glm::dvec4(scene.sphere.centre, 1.0);
  const postfx::CasterMesh caster = mesh.caster(model, glass);
  // The receivers (the floor) and the host's shadow map (the floor and the sphere), along the
  // refracted sun.
  const glm::dvec3 down = refractedSun(scene);
  const glm::dvec3 floorCentre(scene.sphere.centre.x, scene.planeY, scene.sphere.centre.z);
  const reference::ReceiverMap receivers(-down, floorCentre, 6.0, scene.planeY, 1024);
  const glm::dvec4 occluder(scene.sphere.centre, scene.sphere.radius);
  const reference::ReceiverMap shadow(-down, floorCentre, 6.0, scene.planeY, 1024, 0.0,
                                      options.shadowless ? nullptr : &occluder);

  postfx::CreateDesc create;
  create.features = postfx::Feature::ObjectCaustics;
  if (options.volume) create.features = create.features | postfx::Feature::VolumeCaustics;
  if (options.godRays)
    create.features = create.features | postfx::Feature::GodRays | postfx::Feature::ShadowMask;
  create.depthConvention = postfx::DepthConvention::ReverseZ;
  create.normalEncoding = postfx::NormalEncoding::WorldXyz;
  create.waterTexture = postfx::WaterTextureType::Single2D;
  create.memoryBudgetMiB = options.memoryBudgetMiB;
  GLuint flat = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &flat);
  glTextureStorage2D(flat, 1, GL_RG32F, 1, 1);
  const float zero2[2] = {0.0f, 0.0f};
  glTextureSubImage2D(flat, 0, 0, 0, 1, 1, GL_RG, GL_FLOAT, zero2);

  postfx::FrameDesc frame;
  frame.depth = {gbuffer.depth(), GL_DEPTH_COMPONENT32F};
  frame.normal = {gbuffer.normal(), GL_RGBA16F};
  frame.albedo = {gbuffer.albedo(), GL_RGBA8};
  frame.camera.position = glm::dvec3(0.0);
  frame.camera.view = glm::mat4(view.view);
  frame.camera.projection = view.projection;
  frame.sun.direction = scene.towardSun;
  frame.sun.irradiance = glm::vec3(1.0f);
  frame.water.texture = {flat, GL_RG32F};
  frame.water.level = scene.waterLevel;
  frame.water.ior = float(scene.waterIor);
  frame.water.absorption = glm::vec3(scene.absorption);
  frame.water.scattering = glm::vec3(scene.scattering);
  frame.shadow = shadow.desc();
  frame.shadow.bias = 0.02f;
  frame.caustics.enabled = false;
  frame.caustics.model = postfx::CausticsModel::RayDeviation;
  frame.godRays.enabled = options.godRays;
  frame.godRays.intensity = float(scene.phase);
  frame.godRays.resolution = options.godRayResolution;
  frame.godRays.sampleCount = options.godRaySamples;
  frame.godRays.gridSpacing = 0.2f;  // 64 samples reach ~13 m: past the wall
  frame.godRays.surfaceFadeDistance = float(scene.surfaceFade);
  frame.godRays.depthFadeDistance = float(scene.depthFade);
  frame.objectCaustics.casters = &caster;
  frame.objectCaustics.casterCount = 1;
  frame.objectCaustics.receivers = receivers.desc();
  frame.objectCaustics.settings = settings;
  frame.objectCaustics.settings.volume.enabled = options.volume && settings.volume.enabled;
  if (options.hostExtinction) frame.viewExtinction = postfx::ViewExtinction::Host;

  // Point lights above the sphere: each one's receivers the floor seen from it.
  std::deque<reference::LightReceiverMap> lightReceivers;
  std::vector<postfx::LocalLight> lights;
  const int lightCount = scene.pointLightDistance > 0.0 ? std::max(scene.pointLightCount, 1) : 0;
  for (int k = 0; k < lightCount; ++k) {
    const double tilt = lightCount > 1 ? 10.0 * kPi / 180.0 : 0.0, turn = 0.5 * kPi * k;
    const glm::dvec3 up(std::sin(tilt) * std::cos(turn), std::cos(tilt),
                        std::sin(tilt) * std::sin(turn));
    postfx::LocalLight light;
    light.type = postfx::LocalLightType::Point;
    light.position = scene.sphere.centre + up * scene.pointLightDistance;
    light.intensity = scene.pointLightIntensity;
    light.range = 1e6;
    lightReceivers.emplace_back(light.position, -up, 60.0, scene.planeY, 1024, 1000.0);
    light.receivers = lightReceivers.back().desc();
    lights.push_back(light);
  }
  if (lightCount > 0) {
    create.maxLocalLights = lightCount;
    frame.objectCaustics.lights = lights.data();
    frame.objectCaustics.lightCount = lightCount;
    frame.objectCaustics.sunCaustics = false;
  }
  const ReportTarget target(scene.width, scene.height);
  if (options.godRays && options.godRayReference) {
    frame.target = {target.texture(), GL_RGBA32F};
    reference::GodRayInputs inputs;
    if (!reference::captureGodRayInputs(create, frame, inputs, error)) {
      glDeleteTextures(1, &flat);
      return false;
    }
    reference::GodRayReferenceOptions march;
    march.samples = 1024;
    out.godRayReference = reference::renderGodRayReference(create, frame, inputs, march);
  }
  bool ok = true;
  if (options.timedFrames <= 0) {
    postfx::Context* context = nullptr;
    if (postfx::create(create, context) != postfx::Result::Ok) {
      error = std::string("postfx: ") + postfx::lastError(nullptr);
      glDeleteTextures(1, &flat);
      return false;
    }
    frame.target = {target.texture(), GL_RGBA32F};
    const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    glClearTexImage(target.texture(), 0, GL_RGBA, GL_FLOAT, zero);
    ok = postfx::dispatch(*context, frame) == postfx::Result::Ok;
    if (!ok) error = std::string("postfx: ") + postfx::lastError(context);
    postfx::destroy(context);
    if (ok) out.light = readLight(target.texture(), scene.width, scene.height);
  } else {
    PassRun run;
    ok = runPass(create, frame, postfx::Pass::ObjectCaustics, target, options.timedFrames, run,
                 error);
    if (ok) {
      out.medianMs = run.medianMs;
      if (lightCount > 0) {
        out.medianMs = 0.0;
        for (int k = 0; k < lightCount; ++k) out.medianMs += run.stats.objectLight(k).medianMs;
      }
      out.estimatedMs = run.estimated(postfx::Pass::ObjectCaustics);
      out.floorMs = run.floorMs;
      out.light.resize(run.image.size());
      for (size_t i = 0; i < run.image.size(); ++i)
        out.light[i] = glm::dvec3(glm::vec3(run.image[i]));
    }
  }
  glDeleteTextures(1, &flat);
  return ok;
}

std::vector<glm::dvec3> volumeCausticReference(const VolumeCausticScene& scene, int raysPerSide,
                                               unsigned seed, bool progress) {
  const PlaneView view = wallView(scene);
  reference::VolumeCausticCamera camera;
  camera.width = scene.width;
  camera.height = scene.height;
  camera.viewToWorld = glm::transpose(glm::dmat3(view.view));
  camera.p00 = view.projection[0][0];
  camera.p11 = view.projection[1][1];
  camera.distance.resize(size_t(scene.width) * size_t(scene.height));
  for (int y = 0; y < scene.height; ++y)
    for (int x = 0; x < scene.width; ++x) {
      const double nx = ((x + 0.5) / scene.width * 2.0 - 1.0) / camera.p00;
      const double ny = ((y + 0.5) / scene.height * 2.0 - 1.0) / camera.p11;
      camera.distance[size_t(y) * size_t(scene.width) + size_t(x)] =
          scene.wallDistance * std::sqrt(nx * nx + ny * ny + 1.0);
    }
  reference::VolumeCausticMedium medium;
  medium.waterLevel = scene.waterLevel;
  medium.waterIor = scene.waterIor;
  medium.towardSun = scene.towardSun;
  medium.sigmaS = scene.scattering;
  medium.sigmaT = scene.scattering + scene.absorption;
  medium.phase = scene.phase;
  medium.surfaceFade = scene.surfaceFade;
  medium.depthFade = scene.depthFade;
  return reference::renderVolumeCausticReference(scene.sphere, scene.planeY, medium, camera,
                                                 raysPerSide, seed, progress);
}

ConeError coneError(const std::vector<glm::dvec3>& image, const std::vector<glm::dvec3>& reference,
                    double threshold) {
  ConeError e;
  if (image.size() != reference.size() || reference.empty()) return e;
  std::vector<double> g;
  g.reserve(reference.size());
  for (const glm::dvec3& r : reference) g.push_back(r.g);
  std::nth_element(g.begin(), g.begin() + std::ptrdiff_t(g.size() * 99 / 100), g.end());
  const double cut = threshold * g[g.size() * 99 / 100];
  double sa = 0, sr = 0, saa = 0, srr = 0, sar = 0, err = 0;
  for (size_t i = 0; i < reference.size(); ++i) {
    const double r = reference[i].g, a = image[i].g;
    if (threshold > 0.0 && (!(r >= cut) || !(cut > 0.0))) continue;
    ++e.pixels;
    sa += a;
    sr += r;
    saa += a * a;
    srr += r * r;
    sar += a * r;
    err += (a - r) * (a - r);
  }
  if (e.pixels == 0 || !(srr > 0.0)) return e;
  const double n = e.pixels;
  e.relativeRmse = std::sqrt(err / srr);
  e.fluxRatio = sa / sr;
  const double va = saa - sa * sa / n, vr = srr - sr * sr / n;
  e.correlation = va > 0.0 && vr > 0.0 ? (sar - sa * sr / n) / std::sqrt(va * vr) : 0.0;
  return e;
}

}  // namespace ocean::validation
