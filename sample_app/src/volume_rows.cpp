#include "volume_rows.h"

#include <cstdio>

#include <volume_caustic_run.h>

#include "image_output.h"

namespace ocean {
namespace {

bool writeLight(const std::string& path, int width, int height,
                const std::vector<glm::dvec3>& light, std::string& error) {
  std::vector<float> rgb;
  rgb.reserve(light.size() * 3);
  for (const glm::dvec3& p : light)
    for (int c = 0; c < 3; ++c) rgb.push_back(float(p[c]));
  return writeExrChannels(path, width, height, {"R", "G", "B"}, rgb, error);
}

}  // namespace

bool measureVolumeRows(const VolumeReportSettings& settings, std::vector<report::Row>& rows,
                       std::string& note, std::string& error) {
  const validation::VolumeCausticScene scene =
      validation::glassSphereInWater(settings.width, settings.height);
  std::fprintf(stderr, "report: volume caustics reference, %d rays per side, two seeds\n",
               settings.referenceRaysPerSide);
  const std::vector<glm::dvec3> a =
      validation::volumeCausticReference(scene, settings.referenceRaysPerSide, 0);
  const std::vector<glm::dvec3> b =
      validation::volumeCausticReference(scene, settings.referenceRaysPerSide, 1);
  std::vector<glm::dvec3> reference(a.size());
  for (size_t i = 0; i < a.size(); ++i) reference[i] = 0.5 * (a[i] + b[i]);
  // Half the two seeds' difference: the mean's own noise.
  const validation::ConeError noise = validation::coneError(a, reference);
  char text[512];
  std::snprintf(text, sizeof(text),
                "Volume caustics: a glass ball (R 0.5 m, IOR 1.5 in water) 5 m from the camera, "
                "the sun 25 degrees from the zenith, its cone to a floor 3 m below its centre, "
                "seen against a wall 8 m away at %dx%d; reference: 2 x %d^2 rays traced exactly "
                "through the ball, marched through the pixels in half-pixel steps; error in the "
                "cone (reference >= 5 %% of its 99th percentile, %d pixels); one seed against "
                "their mean: relative RMSE %.3f.",
                settings.width, settings.height, settings.referenceRaysPerSide, noise.pixels,
                noise.relativeRmse);
  note = text;
  const bool images = !settings.imageDir.empty();
  if (images && !writeLight(settings.imageDir + "/volume_reference.exr", settings.width,
                            settings.height, reference, error))
    return false;
  validation::VolumeCausticOptions off;
  off.volume = false;
  off.timedFrames = settings.timedFrames;
  struct Method {
    const char* name;
    postfx::VolumeCausticsMethod method;
  };
  const Method methods[] = {{"volume caustics, beams", postfx::VolumeCausticsMethod::Beams},
                            {"volume caustics, lines", postfx::VolumeCausticsMethod::Lines}};
  for (int grid : settings.grids) {
    postfx::ObjectCausticsSettings s;
    s.gridSize = grid;
    validation::VolumeCausticRun without;
    if (!validation::runVolumeCaustic(scene, s, off, without, error)) return false;
    for (const Method& m : methods) {
      std::fprintf(stderr, "report: %s, grid %d\n", m.name, grid);
      s.volume.method = m.method;
      validation::VolumeCausticOptions on;
      on.timedFrames = settings.timedFrames;
      validation::VolumeCausticRun with;
      if (!validation::runVolumeCaustic(scene, s, on, with, error)) return false;
      std::vector<glm::dvec3> volume(with.light.size());
      for (size_t i = 0; i < volume.size(); ++i) volume[i] = with.light[i] - without.light[i];
      const validation::ConeError e = validation::coneError(volume, reference);
      report::Row row;
      row.pass = "volume_caustics";
      row.method = m.name;
      row.setting = "grid " + std::to_string(grid);
      row.medianMs = with.medianMs;
      row.estimatedMs = with.estimatedMs;
      row.floorMs = with.floorMs;
      row.relativeRmse = e.relativeRmse;
      row.correlation = e.correlation;
      row.width = settings.width;
      row.height = settings.height;
      char extra[160];
      std::snprintf(extra, sizeof(extra),
                    "flux in the cone %.3f of the reference's; the pass without the volume %.3g ms",
                    e.fluxRatio, without.medianMs);
      row.note = extra;
      rows.push_back(row);
      const bool lines = m.method == postfx::VolumeCausticsMethod::Lines;
      if (images && grid == settings.grids.back() &&
          !writeLight(settings.imageDir + (lines ? "/volume_lines.exr" : "/volume_beams.exr"),
                      settings.width, settings.height, volume, error))
        return false;
    }
  }
  // The shafts and the cone together: the god rays (the shadow the ball casts in the host's
  // shadow map included) and the volume caustics as a host draws them, against the god-ray
  // reference of the same frame plus the traced beams.
  {
    std::fprintf(stderr, "report: god-ray reference of the ball's frame (1024 segments)\n");
    validation::VolumeCausticOptions dense;
    dense.godRays = true;
    dense.volume = false;
    dense.godRayReference = true;
    validation::VolumeCausticRun shafts;
    if (!validation::runVolumeCaustic(scene, {}, dense, shafts, error)) return false;
    std::vector<glm::dvec3> whole(reference.size());
    for (size_t i = 0; i < whole.size(); ++i) whole[i] = shafts.godRayReference[i] + reference[i];
    struct Variant {
      const char* name;
      postfx::GodRayResolution resolution;
      int samples;
    };
    const Variant variants[] = {
        {"god rays + volume caustics (beams), quarter res", postfx::GodRayResolution::Quarter, 16},
        {"god rays + volume caustics (beams), full res", postfx::GodRayResolution::Full, 32}};
    for (const Variant& v : variants) {
      std::fprintf(stderr, "report: %s\n", v.name);
      validation::VolumeCausticOptions on;
      on.godRays = true;
      on.godRayResolution = v.resolution;
      on.godRaySamples = v.samples;
      on.timedFrames = settings.timedFrames;
      validation::VolumeCausticRun run;
      if (!validation::runVolumeCaustic(scene, {}, on, run, error)) return false;
      const validation::ConeError cone = validation::coneError(run.light, whole, 0.0);
      report::Row row;
      row.pass = "volume_caustics_shafts";
      row.method = v.name;
      row.setting = std::to_string(v.samples) + " samples";
      row.medianMs = run.medianMs;
      row.estimatedMs = run.estimatedMs;
      row.floorMs = run.floorMs;
      row.relativeRmse = cone.relativeRmse;
      row.correlation = cone.correlation;
      row.width = settings.width;
      row.height = settings.height;
      row.note =
          "whole frame (the shafts, the ball's shadow in them and its cone) against the "
          "god-ray reference plus the traced beams; time: the object caustics pass, the god "
          "rays apart";
      rows.push_back(row);
    }
  }
  // Cost at the users' size: each method with the sun through the ball, then with four point
  // lights (the same ball, each light's trace and volume timed on its own, summed).
  if (settings.costWidth <= 0) return true;
  for (int lights : {0, 4}) {
    validation::VolumeCausticScene cost =
        validation::glassSphereInWater(settings.costWidth, settings.costHeight);
    if (lights > 0) {
      cost.waterLevel = 100.0;  // the lights under water too
      cost.pointLightDistance = 6.0;
      cost.pointLightCount = lights;
      cost.pointLightIntensity = glm::vec3(36.0f);  // the sun's irradiance at the ball
    }
    const std::string what = lights > 0 ? "four point lights" : "the sun";
    validation::VolumeCausticRun without;
    if (!validation::runVolumeCaustic(cost, {}, off, without, error)) return false;
    for (const Method& m : methods) {
      std::fprintf(stderr, "report: %s, %s, %dx%d\n", m.name, what.c_str(), settings.costWidth,
                   settings.costHeight);
      postfx::ObjectCausticsSettings s;
      s.volume.method = m.method;
      validation::VolumeCausticOptions on;
      on.timedFrames = settings.timedFrames;
      validation::VolumeCausticRun with;
      if (!validation::runVolumeCaustic(cost, s, on, with, error)) return false;
      report::Row row;
      row.pass = "volume_caustics_cost";
      row.method = std::string(m.name) + ", " + what;
      row.setting = "grid " + std::to_string(s.gridSize);
      row.medianMs = with.medianMs;
      row.estimatedMs = with.estimatedMs;
      row.floorMs = with.floorMs;
      row.width = settings.costWidth;
      row.height = settings.costHeight;
      char extra[160];
      std::snprintf(extra, sizeof(extra), "the object caustics without the volume %.3g ms",
                    without.medianMs);
      row.note = extra;
      rows.push_back(row);
    }
  }
  return true;
}

}  // namespace ocean
