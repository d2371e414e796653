#pragma once
// Traced reference of a frame's seabed caustics: the irradiance that sunlight refracted by the
// frame's own water surface delivers to every surface point the camera sees, by photon tracing
// against the scene's real triangles (Embree) and density estimation at each pixel.
//
// Model:
//   * A parallel sun beam crosses the mean water plane; photons are stratified over it, so each
//     stands for an equal share of horizontal beam area within its launch cell. Each meets the
//     height field y = level + h(x, z) (found by Newton's method along the sun, falling back
//     to the seabed reference's march), is refracted by Snell's law through the normal
//     given by the surface's slopes and weighted by the unpolarised Fresnel transmittance
//     relative to flat water's. Geometry above the water can shade the photon before it enters.
//   * The refracted photon is traced (Embree) to its first hit on the scene's triangles; a hit
//     on a face turned away from it (its interpolated normal) absorbs it.
//   * Object caustics (FrameTraceDesc::casters): a photon whose first hit is a glass or metal
//     caster lights the caster's surface there as any surface, and its light goes on through
//     the caster (caster_light_path.h) to the ordinary surface it reaches, which gathers it in
//     a second, per-channel estimate (objectIrradiance). This mirrors the host's split: its
//     shadow map keeps the casters opaque, so the seabed estimate has their shadow, and the
//     object-caustic light is what the plugin adds back. Without casters every triangle is
//     opaque, as before.
//   * Irradiance at pixel i's surface point q_i (normal n_i) is the kernel density estimate
//         E_i = sum_photons w K(|x - q_i|),  K(d) = 2 / (pi r_i^2) (1 - d^2 / r_i^2),  d < r_i,
//     an Epanechnikov kernel on a disc of radius r_i = max(kernelScale * |q_i| * (radians per
//     pixel) / sqrt(max(|cos(view, n_i)|, 1/16)), minKernelRadius) (the disc has the area of
//     about pi pixel footprints), over photons whose surface normal is within 60 degrees of n_i.
//     Units: flux per unit surface area with flat water giving 1 on a horizontal receiver; no
//     absorption. Under flat water and no occluders a surface of normal n receives max(n.u, 0) /
//     u.y, u the unperturbed refracted sun reversed (the "flat irradiance").
//   * Noise: E_i is the mean of independent batches (each a complete stratified launch with its
//     own jitter); its standard error is estimated from the batches' scatter, sqrt(var / B),
//     and stated relative to max(E_i, flat irradiance, 0.2): relative where the caustic is
//     bright, relative to the unperturbed light where it is dark (and to a fifth of a
//     horizontal receiver's for surfaces nearly edge-on to the light). Batches are added, at
//     least minBatches, until the `noiseQuantile` of that noise over lit pixels is below
//     `targetNoise`, or maxBatches.
//   * Launch density: cells of the water plane get the photon density that the receivers their
//     light can reach need for kernelPhotonsPerBatch photons per kernel per batch (times
//     sparseBoost for kernels so large that their cells launch single random photons; a pixel's
//     light enters at most the largest slope drift from where flat water would bring it).
//   * Reflected light above the water (FrameTraceDesc::reflected): a second launch, planned for
//     the receivers above the level (FrameReceivers::above) as the first is for those under
//     it, with photons of its own random streams, so that the refracted light's photons, sums
//     and results are bit for bit those of a trace without it. Each photon that meets the water
//     (the same entry, normal and sun occlusion as a refracted one) is mirrored about the local
//     normal, weighted by the unpolarised Fresnel reflectance there relative to flat water's,
//     R(cos_local) / R(sun.y), and traced (Embree) to its first hit; a face turned toward it
//     gathers it in a kernel estimate of its own (reflectedIrradiance), one turned away absorbs
//     it. A reflected ray that runs into a later wave (a low sun) is mirrored again there
//     (weight times R; the refracted share is not followed), up to four times. Units: flat
//     water's reflected flux on a horizontal receiver facing down = 1, so a flat sea gives
//     max(n . l_r, 0) / |l_r.y| on a surface of normal n, l_r = (sun.x, -sun.y, sun.z).
//     A kernel whose disc reaches under the level (a wall or hull at the waterline) is divided
//     by its weight's share above it, where alone the reflected light lands.
//     Casters are opaque to it (it lights their surface, not what lies behind them).
// Deterministic: each cell's photons come from a hash of (seed, batch, cell); sums are kept in
// 64-bit fixed point, so the result is bit-identical for any thread count.
#include <cstdint>
#include <functional>
#include <vector>

#include <glm/glm.hpp>

#include "caster_light_path.h"
#include "embree_scene.h"
#include "frame_receivers.h"
#include "seabed_reference.h"

namespace ocean::reference {

struct FrameTraceProgress {
  int batch = 0;
  std::uint64_t photons = 0;
  // Over lit pixels, with FrameTraceDesc::reflected also the pixels lit by the flat mirror.
  double noiseMedian = 0.0, noiseQuantile = 0.0, noiseMax = 0.0;
  // The reflected light's share of those (over the mirror-lit pixels); 0 without it.
  bool reflected = false;
  size_t reflectedLitPixels = 0;
  double reflectedNoiseMedian = 0.0, reflectedNoiseQuantile = 0.0, reflectedNoiseMax = 0.0;
  double seconds = 0.0;
  bool done = false, converged = false;
};

// A point or spot light under the water whose light through the casters the trace follows (its
// direct light is the host's own): photons stratified over the cone of directions to each
// caster's bounding sphere, each carrying intensity x spot falloff x its solid angle, absorbed
// by the water along the straight parts of its path.
struct TracedLight {
  glm::dvec3 position{0.0};         // world (m)
  glm::dvec3 axis{0.0, -1.0, 0.0};  // spot axis, unit
  bool spot = true;                 // false: a point light (no cone)
  double outerHalfAngle = 0.5;      // spot: radians, light stops here
  double innerHalfAngle = 0.4;      // spot: radians, full light within
  glm::dvec3 intensity{1.0};        // per channel (the plugin's LocalLight::intensity)
  double range = 1e30;              // casters farther than this cast nothing (its contract)
};

struct FrameTraceDesc {
  glm::dvec3 towardSun{0.0, 1.0, 0.0};  // unit vector toward the sun, y > 0
  double ior = 1.333;
  // Angular radius of the sun's disc (radians, >= 0): each photon comes from a direction
  // uniform over it (0: a point sun, every photon parallel).
  double sunAngularRadius = 0.0;
  double kernelScale = 1.0;  // kernel radius in (area-matched) pixel footprints, > 0
  // Smallest kernel radius (m): near the camera a pixel-sized kernel would need photon
  // densities beyond any budget; caustic features are larger than this.
  double minKernelRadius = 0.01;
  double targetNoise = 0.05;
  double noiseQuantile = 0.99;  // of lit pixels' noise that must reach targetNoise
  int minBatches = 8;           // the noise is measured from the scatter of batches: enough of them
  int maxBatches = 24;
  // Photons a kernel of a pixel lit as under flat water receives per batch (the launch
  // density is planned for it). Poisson counting alone would give a relative error of
  // sqrt(4 / (3 N)) per batch (33 % for 12); stratified launching does several times better.
  double kernelPhotonsPerBatch = 12.0;
  // ... times this where a cell would launch less than one photon per batch (Poisson counting,
  // no stratification gain).
  double sparseBoost = 8.0;
  double cellSize = 0.25;  // launch cells on the water plane (m)
  // Photons per batch at most: a plan above it is thinned uniformly (then the target noise
  // may not be reached, which the result says).
  std::uint64_t maxPhotonsPerBatch = 200'000'000;
  std::uint64_t seed = 1;
  int threads = 2;
  // Per mesh of the EmbreeScene: its caster material (glass or metal whose light the trace
  // follows), or none (opaque). Empty: no casters.
  CasterMaterials casters;
  // Local lights whose light through the casters is traced (with casters only; lights above
  // the water are left out). Their photons per batch follow the receivers' kernels, at most
  // maxLightPhotonsPerBatch per light and caster.
  std::vector<TracedLight> lights;
  glm::dvec3 waterAbsorption{0.0};  // 1/m, per channel: the local lights' photons
  std::uint64_t maxLightPhotonsPerBatch = 4'000'000;
  // Also trace the sunlight the water reflects up onto the receivers above the level
  // (FrameTraceResult::reflectedIrradiance); its noise then counts toward convergence.
  bool reflected = false;
  std::function<void(const FrameTraceProgress&)> progress;  // after every batch
};

struct FrameTraceResult {
  // Per pixel (FrameReceivers order); 0 where the pixel is no valid receiver.
  std::vector<double> irradiance;      // traced, flat water on a horizontal receiver = 1
  std::vector<double> flatIrradiance;  // max(n.u, 0) / u.y: flat water, no occluders
  std::vector<double> standardError;   // of irradiance
  std::vector<double> noise;           // standardError / max(irradiance, flatIrradiance)
  std::vector<double> kernelRadius;    // m (above the level too, with reflected light)
  // Light that went through (or off) a caster, per channel, in the units of `irradiance`;
  // empty without casters. Its batch scatter is part of `standardError` and `noise`, which
  // are of the sum irradiance + mean(objectIrradiance).
  std::vector<glm::dvec3> objectIrradiance;
  // 1 where the unperturbed refracted sun ray up from the point (or the ray to a traced local
  // light lighting it) first meets a caster: the casters' shadows, where most object caustics
  // land. Empty without casters.
  std::vector<std::uint8_t> casterShadow;
  // Local lights' light through the casters, per channel (intensity / m^2: the plugin's
  // light units before albedo), and each pixel's direct light from them without casters
  // (mean of the channels, same units: the unit of their noise). Empty without lights.
  std::vector<glm::dvec3> localIrradiance;
  std::vector<double> localDirect;
  double localDirectMedian = 0.0;  // of localDirect over the pixels the lights reach
  std::uint64_t lightPhotonsPerBatch = 0;
  // 1 where flat-water sunlight reaches the point: valid, facing the refracted sun, and no
  // triangle on the unperturbed refracted ray up to the water nor above it toward the sun.
  std::vector<std::uint8_t> lit;
  size_t litPixels = 0;
  size_t casterShadowPixels = 0;
  // Reflected light above the water (FrameTraceDesc::reflected), per pixel; empty without it,
  // 0 where the pixel is no receiver above the level. Units: flat water's reflected flux on a
  // horizontal receiver facing down = 1.
  std::vector<double> reflectedIrradiance;
  std::vector<double> flatReflected;  // max(n . l_r, 0) / |l_r.y|: flat water, no occluders
  std::vector<double> reflectedStandardError;
  std::vector<double> reflectedNoise;  // its error / max(reflected, flatReflected, 0.2)
  // 1 where flat water's mirror light reaches the point: above the level, facing l_r, nothing
  // on the mirror ray down from it to the level, and the water point there sunlit.
  std::vector<std::uint8_t> reflectedLit;
  size_t reflectedLitPixels = 0;
  double reflectedNoiseMedian = 0.0, reflectedNoiseQuantile = 0.0, reflectedNoiseMax = 0.0;
  std::uint64_t reflectedPhotonsPerBatch = 0;  // of photonsPerBatch
  // Photons, over all batches, whose water entry faced away from the sun (the back of a wave:
  // no light enters or is reflected there), of the refracted and the reflected launch; and
  // reflected photons whose light went back into the water (mirrored down, or more than four
  // times between waves, or grazing them too long) and those mirrored by a later wave.
  std::uint64_t backOfWavePhotons = 0, reflectedBackOfWavePhotons = 0;
  std::uint64_t reflectedIntoWaterPhotons = 0, reflectedReboundPhotons = 0;
  // Over lit pixels and the casters' shadows (with reflected light, also its mirror-lit pixels'
  // reflectedNoise).
  double noiseMedian = 0.0, noiseQuantile = 0.0, noiseMax = 0.0;
  std::uint64_t photons = 0;
  std::uint64_t photonsPerBatch = 0;
  int batches = 0;
  bool converged = false;
  double seconds = 0.0;
};

// `scene` must be built relative to receivers.camera (EmbreeScene::create's origin). `water`
// is sampled at world x, z and gives heights relative to receivers.level.
FrameTraceResult traceFrameCaustics(const Surface& water, const EmbreeScene& scene,
                                    const FrameReceivers& receivers, const FrameTraceDesc& desc);

}  // namespace ocean::reference
