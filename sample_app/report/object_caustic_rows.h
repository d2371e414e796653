#pragma once
// The report's object-caustics rows: the glass sphere over a plane
// (ocean::reference::glassSphereOverPlane) at several caustic-map sizes, ray-grid sizes and
// receiver-hit iteration counts, each timed (with its floor) and compared with exact CPU ray
// tracing of the same sphere.
//
// The host is one with glass but no water simulation: no water texture, the level far below, a
// flat receiver G-buffer seen from above and the receiver depth map of the plane seen from the
// sun. Error columns: the relative RMSE (green channel) of the map resampled onto a fixed grid
// of bins perpendicular to the light, against the reference traced into the same bins (so maps
// of every size meet one converged reference); the note holds the focus position error (% of
// the radius) and the flux error, measured as the accuracy test does (reference traced into
// each GPU map and blurred by the splat).
#include <string>
#include <vector>

#include "pass_runner.h"
#include "report_table.h"

namespace ocean::report {

struct ObjectCausticVariant {
  enum class Sweep { MapSize, GridSize, Iterations, Splat };
  std::string method;  // the plot's series
  Sweep sweep;         // what varies along it: named first in the setting (the plot's label)
  int mapSize, gridSize, iterations;
  float splatRadius;  // texels
  // Every other setting at its default (footprint 2x, not the sweep's 3x); the sphere under
  // 10 m of water (lit by the refracted sun, relative IOR 1.5 / 1.333) when underWater.
  bool defaults = false;
  bool underWater = false;
};

struct ObjectCausticReportSettings {
  std::vector<ObjectCausticVariant> variants;  // runs shared where two series meet
  int timedFrames = 16;
  int referenceRaysPerSide = 3000;  // per seed (two seeds) for the binned reference
  int focusRaysPerSide = 1200;      // per row, into the GPU map, for focus and flux
  int binCount = 80;                // per side of the bin grid...
  double binSide = 3.2;             // ...covering this many metres around the sphere's axis
  // The point- and spot-light rows (light_caustic_run.h's scenes, every setting at its
  // default): rays per side of the reference (per seed, two seeds), and the block of pixels
  // averaged into one compared bin.
  int lightReferenceRaysPerSide = 1500;
  int lightBinBlock = 4;
};

// The full sweep (map 256/512/1024; grid 64/128/256/512; iterations 1/3/5; splat 0.5/1/2 at
// map 1024) or the quick one; both end with the default settings in air and under water.
ObjectCausticReportSettings objectCausticSweep(bool quick);

// `target`: the report's timing target (its size is the G-buffer's). Appends rows (the sun's,
// then the point and spot lights': the ball lens lit by a point light 2 m away in air and under
// water, a spot's cone edge cutting its caustic hard and soft); `note` gets the scenes and the
// reference's convergence. Progress on stderr.
bool measureObjectCaustics(const validation::ReportTarget& target,
                           const ObjectCausticReportSettings& settings, std::vector<Row>& rows,
                           std::string& note, std::string& error);

}  // namespace ocean::report
