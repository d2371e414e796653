#pragma once
// CPU reference for seabed caustics: converged light tracing, in double, of sunlight through a
// water surface onto one or more receivers under it.
//
// Model (the physics the plugin's caustic passes approximate):
//   * A parallel sun beam. Rays are stratified over their crossing of the mean water plane
//     (y = level), so every ray stands for an equal cross-section of the beam measured on a
//     horizontal plane; flux per unit horizontal area is the same above any such plane.
//   * Each ray is intersected with the height field y = level + h(x, z) (marched from above,
//     refined by regula falsi), refracted by Snell's law through the normal given by the
//     surface's slopes and weighted by the unpolarised Fresnel transmittance of that hit.
//   * The refracted ray is intersected with each receiver (a flat seabed at a fixed depth, or a
//     height field seabed given by a callback) and its weight binned on a horizontal grid.
//   * Irradiance is normalised so that flat water gives exactly 1 on a flat receiver: weights
//     are divided by the flat-water transmittance, bins by their area. Beer-Lambert absorption
//     along the in-water path is optional (0 by default: the plugin's raw caustic output
//     excludes absorption).
// Convergence: the per-bin relative standard error is estimated as sqrt(sum w^2) / sum w, which
// is 1/sqrt(hits) for equal weights (conservative for stratified sampling, whose true error
// falls faster). Batches of rays are added until the median over bins is below the target, or
// the ray cap is reached (reported).
// Deterministic: every stratum's jitter comes from a hash of (batch, row, column), each thread
// owns fixed rows and the partial sums are merged in thread order.
#include <cstdint>
#include <functional>
#include <vector>

#include <glm/glm.hpp>

namespace ocean::reference {

// The water surface at one horizontal position (relative to the mean level).
struct SurfaceSample {
  double height = 0.0;                // m above the mean level
  double slopeX = 0.0, slopeZ = 0.0;  // dh/dx, dh/dz
};

class Surface {
 public:
  virtual ~Surface() = default;
  // World x, z (m).
  virtual SurfaceSample sample(double x, double z) const = 0;
  // Bounds the tracer needs: |height| <= maxHeight(), |slope vector| <= maxSlope(), and the
  // smallest horizontal feature (m) it must not step over when marching a ray.
  virtual double maxHeight() const = 0;
  virtual double maxSlope() const = 0;
  virtual double featureSize() const = 0;
};

// Horizontal grid of bins: bin (i, j) covers world x in [origin.x + i bx, origin.x + (i+1) bx),
// z in [origin.y + j bz, ...) with bx = binSize, bz = binSizeZ (0: square bins). Stored
// row-major, index j * countX + i.
struct BinGrid {
  glm::dvec2 origin{0.0};
  double binSize = 1.0;
  double binSizeZ = 0.0;
  int countX = 1, countZ = 1;
  glm::dvec2 size() const { return {binSize, binSizeZ > 0.0 ? binSizeZ : binSize}; }
};

struct Receiver {
  // Flat seabed this many metres below the mean level (> 0), used when depthAt is empty.
  double depth = 5.0;
  // Height-field seabed: depth below the mean level (m, > 0) at world (x, z). depth must then
  // bound it from above (max depth) and minDepth from below.
  std::function<double(double x, double z)> depthAt;
  double minDepth = 0.0;
  double featureSize = 0.25;  // smallest horizontal feature of depthAt (m): march step

  static Receiver flat(double depthBelowLevel) {
    Receiver r;
    r.depth = depthBelowLevel;
    return r;
  }
};

struct ReferenceDesc {
  glm::dvec3 towardSun{0.0, 1.0, 0.0};  // unit vector toward the sun, y > 0
  double ior = 1.333;
  double absorption = 0.0;  // Beer-Lambert coefficient per metre of in-water path, >= 0
  // Angular radius of the sun's disc (radians, >= 0): each ray comes from a direction uniform
  // over it (0: a point sun).
  double sunAngularRadius = 0.0;
  BinGrid bins;
  std::vector<Receiver> receivers;
  double targetRelativeError = 0.01;  // stop when the median per-bin error is below this
  std::uint64_t maxRays = 400'000'000;
  // Rays per bin side per batch: a batch launches raysPerBinSide^2 rays per bin area.
  int raysPerBinSide = 12;
  int threads = 2;
  bool progress = true;  // one line per batch on stderr
  const char* label = "seabed reference";
};

struct ReceiverResult {
  std::vector<double> irradiance;     // per bin, flat water = 1
  std::vector<double> relativeError;  // per bin, estimated standard error / value
  std::vector<std::uint64_t> hits;    // rays binned
  double medianRelativeError = 1.0;
};

struct ReferenceResult {
  std::vector<ReceiverResult> receivers;
  std::uint64_t rays = 0;
  int batches = 0;
  bool converged = false;     // every receiver's median error reached the target before the cap
  double launchMargin = 0.0;  // m the launch window extends past the shifted bin region
};

// Unpolarised Fresnel transmittance from air into a medium of index `ior` at an incidence
// cosine cosIncident in [0, 1]: 1 - (Rs + Rp) / 2.
double fresnelTransmittance(double cosIncident, double ior);
// The reflected share at the same incidence: (Rs + Rp) / 2 (the two add to 1 up to rounding).
double fresnelReflectance(double cosIncident, double ior);

// Direction of a ray going DOWN into the water, refracted from the sun at a surface with the
// given slopes; y < 0 except for degenerate (near-vertical) normals.
glm::dvec3 refractSunRay(const glm::dvec3& towardSun, double slopeX, double slopeZ, double ior);

// Where the sun ray that crosses the mean water plane at world (u, v) first meets the surface
// (marched from above the crests, refined by regula falsi), and the surface there. `sun` is the
// unit vector toward the sun, y > 0. Shared by every tracer of the water's own surface.
glm::dvec3 sunRayHitsSurface(const Surface& surface, const glm::dvec3& sun, double u, double v,
                             SurfaceSample& at);

// Largest horizontal drift, per metre of descent, that a water normal tilted by at most
// maxSlope adds to the flat-water refracted sun ray (sampled densely over such normals).
double maxSlopeDrift(const glm::dvec3& sun, double ior, double maxSlope);

ReferenceResult traceSeabedCaustics(const Surface& surface, const ReferenceDesc& desc);

}  // namespace ocean::reference
