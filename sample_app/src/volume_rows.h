#pragma once
// The report's volume caustics rows: the glass sphere in water (ocean::validation::
// glassSphereInWater) seen from the side, its cone's in-scattered light drawn as beams and as
// lines at several ray grids, each against the traced beams (the CPU reference's rays, 1500 per
// side, marched through every pixel they cross) inside the cone, and the object caustics pass's
// time with the volume caustics against the same pass without them and against the floor.
#include <string>
#include <vector>

#include <report_table.h>

namespace ocean {

struct VolumeReportSettings {
  int width = 640, height = 360;
  std::vector<int> grids{64, 128, 256, 512};
  int referenceRaysPerSide = 1500;  // per seed, two seeds
  int timedFrames = 16;
  // Cost rows at the size users run (no error: the reference is the 640x360 rows' job): the
  // default settings with the sun through one caster, and with four point lights.
  int costWidth = 1280, costHeight = 720;
  // Where the reference's and each method's light at the last grid go (volume_reference.exr,
  // volume_beams.exr, volume_lines.exr, linear RGB); "" writes none.
  std::string imageDir;
};

// Appends one row per method and grid; `note` says how the reference was made and what the
// volume adds to the pass. Progress on stderr.
bool measureVolumeRows(const VolumeReportSettings& settings, std::vector<report::Row>& rows,
                       std::string& note, std::string& error);

}  // namespace ocean
