#include "object_caustic_rows.h"

#include <epoxy/gl.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <tuple>

#include <object_caustics_metrics.h>
#include <object_caustics_reference.h>
#include <object_caustics_scene.h>

#include "error_metrics.h"
#include "light_caustic_run.h"
#include "plane_gbuffer.h"

namespace ocean::report {
namespace {

namespace ref = ocean::reference;

constexpr double kCameraHeight = 5.0;  // m above the plane: sees +-2.9 m across the image
constexpr double kReceiverHalf = 4.0;  // m, half side of the receiver map's view
constexpr int kReceiverMapSize = 1024;

// At 1024 texels the rays of a 256 grid are sparser than the texels: a wider splat (as the
// accuracy test does) keeps the map from breaking into dots.
float splatRadiusFor(int mapSize) {
  return mapSize >= 1024 ? 2.0f : 1.0f;
}

std::string number(float value) {
  char text[16];
  std::snprintf(text, sizeof(text), "%g", double(value));
  return text;
}

// Every parameter, the swept one first (the plot labels a point with the setting's first number).
std::string settingName(const ObjectCausticVariant& v) {
  using Sweep = ObjectCausticVariant::Sweep;
  if (v.defaults) return v.underWater ? "under water" : "in air";
  const std::string map = "map=" + std::to_string(v.mapSize);
  const std::string grid = "grid=" + std::to_string(v.gridSize);
  const std::string it = "it=" + std::to_string(v.iterations);
  const std::string splat = "splat=" + number(v.splatRadius);
  switch (v.sweep) {
    case Sweep::MapSize:
      return map + " " + grid + " " + it + " " + splat;
    case Sweep::GridSize:
      return grid + " " + map + " " + it + " " + splat;
    case Sweep::Iterations:
      return it + " " + map + " " + grid + " " + splat;
    case Sweep::Splat:
      break;
  }
  return splat + " " + map + " " + grid + " " + it;
}

double sumOfSquares(const std::vector<double>& v) {
  double s = 0.0;
  for (double x : v) s += x * x;
  return s;
}

// Green channel of a size x size map averaged over blocks of block x block bins.
std::vector<double> blockMeans(const std::vector<glm::dvec3>& map, int size, int block) {
  const int n = size / block;
  std::vector<double> out(size_t(n) * n, 0.0);
  for (int y = 0; y < n * block; ++y)
    for (int x = 0; x < n * block; ++x)
      out[size_t(y / block) * n + size_t(x / block)] +=
          map[size_t(y) * size + x].g / double(block * block);
  return out;
}

// The point and spot lights' rows, every setting at its default: the light's own
// GPU time, its error against exact ray tracing into the same bins (two seeds: their half
// difference is the reference's noise), focus and flux in the note. Appends to `note`.
bool measureLightRows(const ObjectCausticReportSettings& settings, int timedFrames,
                      std::vector<Row>& rows, std::string& note, std::string& error) {
  struct Case {
    const char* method;
    const char* setting;
    const char* light;  // in the note
    validation::LightCausticScene scene;
  };
  const int block = settings.lightBinBlock;
  const Case cases[] = {
      {"object caustics, point light", "in air", "point",
       validation::pointLightBallLens(false, 80 * block)},
      {"object caustics, point light", "under water", "point",
       validation::pointLightBallLens(true, 80 * block)},
      {"object caustics, spot light", "hard edge", "spot",
       validation::spotConeCut(0.0, 80 * block)},
      {"object caustics, spot light", "softness 0.5", "spot",
       validation::spotConeCut(0.5, 80 * block)},
  };
  std::string noises;
  for (const Case& c : cases) {
    std::fprintf(stderr, "report: %s, %s\n", c.method, c.setting);
    const validation::LightCausticScene& scene = c.scene;
    validation::LightCausticRun run;
    if (!validation::runLightCaustic(scene, postfx::ObjectCausticsSettings{}, timedFrames, run,
                                     error))
      return false;
    if (run.skip != postfx::LightSkip::None || run.irradiance.empty()) {
      error = std::string("object caustics: the light did not run for ") + c.method;
      return false;
    }
    // The reference into the pixels' bins (focus, flux) and into the compared blocks (error).
    const ref::ReceiverBins pixels = validation::sceneBins(scene);
    ref::ReceiverBins blocks = pixels;
    blocks.size = pixels.size / block;
    const glm::dvec3 water = scene.underWater ? scene.waterAbsorption : glm::dvec3(0.0);
    const int n = settings.lightReferenceRaysPerSide;
    const ref::LocalCausticReference a =
        ref::traceSphereFromLight(scene.sphere, scene.light, blocks, water, n, 1);
    const ref::LocalCausticReference b =
        ref::traceSphereFromLight(scene.sphere, scene.light, blocks, water, n, 2);
    std::vector<double> truth(a.irradiance.size()), halfDifference(a.irradiance.size());
    for (size_t i = 0; i < truth.size(); ++i) {
      truth[i] = 0.5 * (a.irradiance[i].g + b.irradiance[i].g);
      halfDifference[i] = 0.5 * (a.irradiance[i].g - b.irradiance[i].g);
    }
    const validation::ErrorStats stats =
        validation::compareWithReference(blockMeans(run.irradiance, pixels.size, block), truth);
    const ref::LocalCausticReference fine =
        ref::traceSphereFromLight(scene.sphere, scene.light, pixels, water, n, 3);
    const double area = ref::binArea(pixels);
    double gpuFlux = 0.0;
    for (const glm::dvec3& v : run.irradiance) gpuFlux += v.g * area;
    const glm::dvec3 gpuFocus =
        ref::binPoint(pixels, ref::focusTexel(run.irradiance, pixels.size, 4));
    const glm::dvec3 refFocus =
        ref::binPoint(pixels, ref::focusTexel(fine.irradiance, pixels.size, 4));
    Row row;
    row.pass = "object_caustics";
    row.method = c.method;
    row.setting = c.setting;
    row.medianMs = run.medianMs;
    row.estimatedMs = run.estimatedMs;
    row.floorMs = run.floorMs;
    row.relativeRmse = stats.relativeRmse;
    row.correlation = stats.correlation;
    char text[160];
    std::snprintf(text, sizeof(text), "focus %.2f mm (%.2f %% R), flux %+.2f %% (G)",
                  1000.0 * glm::length(gpuFocus - refFocus),
                  100.0 * glm::length(gpuFocus - refFocus) / scene.sphere.radius,
                  100.0 * (gpuFlux / fine.fluxInBins.g - 1.0));
    row.note = text;
    if (&c == &cases[0]) {
      // What the sun costs on the same host and settings, timed right after the light.
      double sunMs = 0.0, sunFloorMs = 0.0;
      if (!timeSunCaustic(scene, postfx::ObjectCausticsSettings{}, timedFrames, sunMs, sunFloorMs,
                          error))
        return false;
      char sun[96];
      std::snprintf(sun, sizeof(sun), "; the sun on this host %.3g ms (light / sun %.2f)", sunMs,
                    run.medianMs / sunMs);
      row.note += sun;
    }
    rows.push_back(row);
    char noise[96];
    std::snprintf(noise, sizeof(noise), "%s%s %s %.2g", noises.empty() ? "" : ", ", c.light,
                  c.setting, std::sqrt(sumOfSquares(halfDifference) / sumOfSquares(truth)));
    noises += noise;
  }
  char text[1200];
  std::snprintf(
      text, sizeof(text),
      " Point and spot lights: a glass ball (R = 0.25 m, IOR 1.5, absorption 0.2, 1, "
      "3 per m) lit by a point light 2 m from its centre, 30 deg off the vertical, over a floor "
      "that cuts the axis at 0.98 of the paraxial image (in air; under water: relative IOR "
      "1.5/1.333, water absorbing 0.35, 0.06, 0.02 per m along both legs); a spot 2 m above a "
      "clear ball, its 20 deg cone tilted 10 deg so that its edge cuts the caustic in half. "
      "Every setting at its default; the light's own time (FrameStats::objectLight), the sun "
      "left out. The plugin's light over a white floor seen from above, %d x %d pixels per "
      "compared bin (80 x 80 bins), against %.3g traced rays in the same bins (noise: %s); "
      "focus and flux in the note against %d^2 rays traced into the pixels.",
      block, block, 2.0 * settings.lightReferenceRaysPerSide * settings.lightReferenceRaysPerSide,
      noises.c_str(), settings.lightReferenceRaysPerSide);
  note += text;
  return true;
}

}  // namespace

ObjectCausticReportSettings objectCausticSweep(bool quick) {
  using Sweep = ObjectCausticVariant::Sweep;
  ObjectCausticReportSettings s;
  for (int map : quick ? std::vector<int>{256, 512} : std::vector<int>{256, 512, 1024})
    s.variants.push_back(
        {"object caustics, map size", Sweep::MapSize, map, 256, 1, splatRadiusFor(map)});
  for (int grid : quick ? std::vector<int>{64, 128, 256} : std::vector<int>{64, 128, 256, 512})
    s.variants.push_back({"object caustics, ray grid", Sweep::GridSize, 512, grid, 1, 1.0f});
  for (int it : quick ? std::vector<int>{1, 3} : std::vector<int>{1, 3, 5})
    s.variants.push_back(
        {"object caustics, hit iterations", Sweep::Iterations, 512, 256, it, 1.0f});
  if (!quick) {
    // The splat sets the map's resolution in metres: narrower at 1024 texels, with the rays of a
    // 512 grid to fill it.
    for (float splat : {0.5f, 1.0f, 2.0f})
      s.variants.push_back(
          {"object caustics, splat (map 1024)", Sweep::Splat, 1024, 512, 1, splat});
  }
  const postfx::ObjectCausticsSettings d;
  for (bool underWater : {false, true})
    s.variants.push_back({"object caustics, defaults", Sweep::MapSize, d.mapSize, d.gridSize,
                          d.iterations, d.splatRadius, true, underWater});
  s.timedFrames = quick ? 6 : 16;
  s.referenceRaysPerSide = quick ? 1500 : 3000;
  s.focusRaysPerSide = quick ? 800 : 1200;
  s.lightReferenceRaysPerSide = quick ? 700 : 1500;
  return s;
}

bool measureObjectCaustics(const validation::ReportTarget& target,
                           const ObjectCausticReportSettings& settings, std::vector<Row>& rows,
                           std::string& note, std::string& error) {
  const ref::SphereOverPlane scene = ref::glassSphereOverPlane();
  const ref::SphereCaster& sphere = scene.sphere;
  const int w = target.width(), h = target.height();
  const validation::PlaneView topDown = validation::topDownView(w, h, kCameraHeight - scene.planeY);
  validation::PlaneGbuffer gbuffer(w, h, topDown);
  const ref::GlMesh mesh = ref::makeSphereMesh(sphere.radius, 160, 80);
  // Under water the light reaching the sphere is the sun refracted by the flat surface, and the
  // glass bends it by its IOR over the water's.
  constexpr double kWaterIor = 1.333;
  const glm::dvec3 travelInWater =
      glm::refract(-scene.towardSun, glm::dvec3(0.0, 1.0, 0.0), 1.0 / kWaterIor);
  const ref::ReceiverMap airReceivers(scene.towardSun, glm::dvec3(0.0), kReceiverHalf, scene.planeY,
                                      kReceiverMapSize);
  const ref::ReceiverMap waterReceivers(-travelInWater, glm::dvec3(0.0), kReceiverHalf,
                                        scene.planeY, kReceiverMapSize);
  postfx::CasterMaterial glass;
  glass.ior = float(sphere.ior);
  glass.absorption = glm::vec3(sphere.absorption);
  glm::dmat4 model(1.0);
  model[3] = glm::dvec4(sphere.centre, 1.0);
  const postfx::CasterMesh caster = mesh.caster(model, glass);

  postfx::CreateDesc create;
  create.features = postfx::Feature::ObjectCaustics;
  create.depthConvention = postfx::DepthConvention::ReverseZ;
  create.normalEncoding = postfx::NormalEncoding::WorldXyz;
  postfx::FrameDesc frame;
  frame.depth = {gbuffer.depth(), GL_DEPTH_COMPONENT32F};
  frame.normal = {gbuffer.normal(), GL_RGBA16F};
  frame.albedo = {gbuffer.albedo(), GL_RGBA8};
  frame.camera.position = {sphere.centre.x, kCameraHeight, sphere.centre.z};
  frame.camera.view = glm::mat4(topDown.view);
  frame.camera.projection = topDown.projection;
  frame.sun.direction = scene.towardSun;
  frame.water.texture = {};     // no water simulation: the host has glass only
  frame.water.level = -1000.0;  // far below: the sphere is lit by the sun itself
  frame.caustics.enabled = false;
  frame.godRays.enabled = false;
  frame.objectCaustics.casters = &caster;
  frame.objectCaustics.casterCount = 1;

  // One run per distinct setting, shared by the series that meet there.
  using Key = std::tuple<int, int, int, float, bool, bool>;
  std::map<Key, Row> done;
  struct Truth {
    postfx::ObjectCausticMap bins;
    std::vector<double> irradiance;
    double noise = 0.0;
  };
  Truth truths[2];  // in air, under water
  long long referenceRays = 0;
  for (size_t k = 0; k < settings.variants.size(); ++k) {
    const ObjectCausticVariant& v = settings.variants[k];
    const Key key{v.mapSize, v.gridSize, v.iterations, v.splatRadius, v.defaults, v.underWater};
    if (auto it = done.find(key); it != done.end()) {
      Row row = it->second;
      row.method = v.method;
      row.setting = settingName(v);
      rows.push_back(row);
      continue;
    }
    std::fprintf(stderr, "report: object caustics %s (%zu/%zu)\n", settingName(v).c_str(), k + 1,
                 settings.variants.size());
    postfx::ObjectCausticsSettings& s = frame.objectCaustics.settings;
    s = postfx::ObjectCausticsSettings{};
    s.mapSize = v.mapSize;
    s.gridSize = v.gridSize;
    s.iterations = v.iterations;
    s.splatRadius = v.splatRadius;
    // As the accuracy test: room for the rim rays beside the sphere.
    if (!v.defaults) s.footprintScale = 3.0f;
    ref::SphereCaster traced = sphere;
    glm::dvec3 towardLight = scene.towardSun;
    frame.objectCaustics.receivers = airReceivers.desc();
    frame.water.level = -1000.0;
    if (v.underWater) {
      traced.ior = sphere.ior / kWaterIor;
      towardLight = -travelInWater;
      frame.objectCaustics.receivers = waterReceivers.desc();
      frame.water.level = 10.0;
      frame.water.ior = float(kWaterIor);
    }
    Truth& truth = truths[v.underWater ? 1 : 0];
    validation::PassRun run;
    if (!validation::runPass(create, frame, postfx::Pass::ObjectCaustics, target,
                             settings.timedFrames, run, error))
      return false;
    const postfx::ObjectCausticMap& placement = run.objectMapPlacement;
    if (run.objectMap.empty()) {
      error = "object caustics: the pass did not run for " + settingName(v);
      return false;
    }

    if (truth.irradiance.empty()) {
      // The bins take the light's axes from the first map (every map of this light has them).
      truth.bins = ref::binGrid(placement, sphere.centre, settings.binSide, settings.binCount);
      const int n = settings.referenceRaysPerSide;
      const ref::CausticReference a =
          ref::traceSphereReference(traced, towardLight, scene.planeY, truth.bins, n, 1);
      const ref::CausticReference b =
          ref::traceSphereReference(traced, towardLight, scene.planeY, truth.bins, n, 2);
      std::vector<double> halfDifference(a.irradiance.size());
      truth.irradiance.resize(a.irradiance.size());
      for (size_t i = 0; i < truth.irradiance.size(); ++i) {
        truth.irradiance[i] = 0.5 * (a.irradiance[i].g + b.irradiance[i].g);
        halfDifference[i] = 0.5 * (a.irradiance[i].g - b.irradiance[i].g);
      }
      // The mean of two independent estimates has the variance of their half difference.
      truth.noise = std::sqrt(sumOfSquares(halfDifference) / sumOfSquares(truth.irradiance));
      referenceRays = 2LL * n * n;
    }
    if (std::abs(glm::dot(glm::normalize(placement.axisU), glm::normalize(truth.bins.axisU)) -
                 1.0) > 1e-9) {
      error = "object caustics: the map's axes changed between settings";
      return false;
    }
    const validation::ErrorStats stats = validation::compareWithReference(
        ref::resampleToBins(run.objectMap, placement, truth.bins), truth.irradiance);

    // Focus and flux as the accuracy test measures them, on this map's own texels.
    const ref::CausticReference local = ref::traceSphereReference(
        traced, towardLight, scene.planeY, placement, settings.focusRaysPerSide);
    const std::vector<glm::dvec3> blurred =
        ref::gaussianBlur(local.irradiance, placement.size, s.splatRadius);
    const glm::dvec3 gpuFocus =
        ref::texelOnPlane(placement, ref::focusTexel(run.objectMap, placement.size), scene.planeY);
    const glm::dvec3 refFocus =
        ref::texelOnPlane(placement, ref::focusTexel(blurred, placement.size), scene.planeY);
    const double focusError = glm::length(gpuFocus - refFocus) / sphere.radius;
    const double fluxError = ref::mapFlux(run.objectMap, placement).g / local.fluxInMap.g - 1.0;

    Row row;
    row.pass = "object_caustics";
    row.method = v.method;
    row.setting = settingName(v);
    row.medianMs = run.medianMs;
    row.estimatedMs = run.estimated(postfx::Pass::ObjectCaustics);
    row.floorMs = run.floorMs;
    row.relativeRmse = stats.relativeRmse;
    row.correlation = stats.correlation;
    char text[160];
    std::snprintf(text, sizeof(text), "focus %.3f %% R, flux %+.2f %% (G); splat sigma %.1f mm",
                  100.0 * focusError, 100.0 * fluxError,
                  1000.0 * double(s.splatRadius) * glm::length(placement.axisU) / placement.size);
    row.note = text;
    done[key] = row;
    rows.push_back(row);
  }

  char text[1400];
  std::snprintf(
      text, sizeof(text),
      "Object caustics: glass sphere (R = 1 m, IOR 1.5, tinted) 0.4 m over a plane, sun 25 deg "
      "from the zenith, a host with no water texture; caustic map over 3x the sphere's "
      "footprint, 5 exit iterations (the 'defaults' rows: every setting at its default, "
      "footprint 2x; under water: 10 m of water above, the refracted sun). Reference: exact "
      "CPU ray tracing (Fresnel at both surfaces, Beer-Lambert inside), %.3g rays binned on %d "
      "x %d bins of %.0f mm perpendicular to the light; its own noise (half the difference of "
      "two seeds) %.2g relative RMSE in air, %.2g under water. Relative RMSE is the green "
      "channel over those bins; focus and flux in the note are against %d^2 rays traced into "
      "each GPU map and blurred by its splat.",
      double(referenceRays), settings.binCount, settings.binCount,
      1000.0 * settings.binSide / settings.binCount, truths[0].noise, truths[1].noise,
      settings.focusRaysPerSide);
  note = text;
  return measureLightRows(settings, settings.timedFrames, rows, note, error);
}

}  // namespace ocean::report
