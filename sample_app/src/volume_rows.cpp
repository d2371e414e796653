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
  return true;
}

}  // namespace ocean
