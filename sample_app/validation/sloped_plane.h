#pragma once
// A planar receiver tilted about the world z axis, seen face-on (plane_gbuffer.h), and the
// horizontal bins of the seabed reference that its pixels fill exactly.
//
// The plane: depth below the level = centreDepth + facing * tan(slope) * (x - centre.x), so its
// unit normal is (facing * sin(slope), cos(slope), 0): facing +1 leans it toward +x. The camera
// sits `viewDistance` along the normal from the centre, looking back along it, image up =
// (cos(slope), -facing * sin(slope), 0) (down the slope), image right = world +z. Pixel column i
// then lies at world z = centre.z + (i + 0.5 - width / 2) * p and row j (GL order, bottom up) at
// x = centre.x + (j + 0.5 - height / 2) * p * cos(slope), p the pixel size on the plane: a pure
// scale, so a block of binPixels x binPixels pixels is exactly one horizontal reference bin of
// binPixels * p * cos(slope) (x) by binPixels * p (z), and every bin covers the same plane area
// at every slope.
//
// Units: the reference bins hold flux per unit HORIZONTAL area, flat water = 1 on a flat floor.
// Under flat water the beam (unit direction L toward the refracted sun) carries 1 / L.y per unit
// area across it, so a surface with normal n gets n.L / L.y per unit of its own area and
// n.L / (L.y n.y) per unit of its horizontal projection. The plugin's raw factor is
// omega * n.L (flat water: omega = 1), so raw / (L.y n.y) is in the bins' units.
#include <vector>

#include <seabed_reference.h>
#include <glm/glm.hpp>

#include "plane_gbuffer.h"

namespace ocean::validation {

struct SlopedPlaneDesc {
  int width = 128, height = 128;      // pixels; multiples of binPixels
  int binPixels = 4;                  // pixels per bin side
  double slopeDegrees = 0.0;          // [0, 80]
  int facing = 1;                     // +1: the normal leans toward +x; -1: toward -x
  glm::dvec3 centre{0.0, -6.5, 0.0};  // world point of the plane at the image centre
  double viewDistance = 4.0;          // m from the centre along the normal to the camera
};

struct SlopedPlane {
  SlopedPlaneDesc desc;
  PlaneView view;
  glm::dvec3 camera{0.0};  // world position
  glm::dvec3 normal{0.0, 1.0, 0.0};
  ocean::reference::BinGrid bins;
  double minDepth = 0.0, maxDepth = 0.0;  // below `level` over the bins (m)

  // The plane as the reference's height-field receiver under a mean level `level`. A plane has
  // no depth bound, which the reference needs (Receiver::depth is where a ray stops looking):
  // the depth is clamped to [minDepth - pad, maxDepth + pad]. That changes nothing for a ray
  // that reaches a bin: before the bin it is above the plane and shallower than maxDepth, so
  // above the clamped surface too. Flat (Receiver::flat) at slope 0.
  ocean::reference::Receiver receiver(double level, double pad = 1.0) const;
  // Mean over each bin's pixels of raw[pixel] * scale; raw is width x height, GL row order.
  std::vector<double> binned(const std::vector<float>& raw, double scale) const;
  // Flat water's value in the bins' units (see the header comment) for the refracted sun L
  // (unit, pointing up toward the sun).
  double flatWaterFlux(const glm::dvec3& towardRefractedSun) const;
};

// `level`: the mean water level; the plane's centre must be under it by more than the plane
// rises over half the view (checked by the caller through minDepth).
SlopedPlane slopedPlane(const SlopedPlaneDesc& desc, double level);

}  // namespace ocean::validation
