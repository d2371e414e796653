#include "frame_caustics_reference.h"
#include "sun_disc.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>

#include <postfx/water/random.h>

#include "core/shared_math.h"  // the plugin's own spot cone and submerged length (shaders/postfx)

#include "local_light_launch.h"
#include "photon_launch_plan.h"
#include "reflected_light_path.h"

namespace ocean::reference {
namespace {

constexpr double kPi = 3.141592653589793;
// Fixed-point scale of the per-pixel sums: integer sums do not depend on the order photons
// arrive in, so any split over threads gives the same bits. A contribution w K is at most
// ~1e4 (a whole-cell photon on a 1 mm kernel), so a batch's sum stays far below 2^63.
constexpr double kSumScale = 4294967296.0;  // 2^32
// Noise is stated relative to at least this irradiance (a fifth of flat water's on a
// horizontal receiver): a surface almost edge-on to the light gets little of it either way.
constexpr double kNoiseFloor = 0.2;
// A photon counts for a pixel only on a surface turned within 60 degrees of the pixel's.
constexpr double kMinNormalAgreement = 0.5;
// Mirrorings of one reflected photon between waves before its light is given up.
constexpr int kMaxMirrorBounces = 4;
// The reflected launch's random streams differ from the refracted one's by this.
constexpr std::uint64_t kMirrorStream = 0x6A09E667F3BCC909ull;

struct Accumulator {
  std::vector<std::int64_t> sum;
  std::vector<std::int64_t> object;     // 3 per pixel (RGB), with casters only
  std::vector<std::int64_t> local;      // 3 per pixel (RGB), with traced local lights only
  std::vector<std::int64_t> reflected;  // with reflected light only
  std::uint64_t backOfWave = 0, mirrorBackOfWave = 0, mirrorIntoWater = 0, mirrorRebounds = 0;
  void reset(size_t n, bool casters, bool lights, bool mirror) {
    sum.assign(n, 0);
    object.assign(casters ? 3 * n : 0, 0);
    local.assign(lights ? 3 * n : 0, 0);
    reflected.assign(mirror ? n : 0, 0);
    backOfWave = mirrorBackOfWave = mirrorIntoWater = mirrorRebounds = 0;
  }
};

// Which of a water photon's paths a launch follows: the refracted light under the water, or
// the reflected light above it (a launch of its own: see the header).
enum class PhotonPath { Refracted, Reflected };

// Where the sun ray through the mean plane at world (u, v) meets the surface: the root of
// g(p) = p - (u, v) - s h(p), s = sun.xz / sun.y, by Newton's method with the surface's own
// slopes as the Jacobian (two or three steps for any slope along the sun below 1 / |s|); the
// seabed reference's march from above the crests where it does not converge.
glm::dvec3 entryPoint(const Surface& water, const glm::dvec3& sun, double u, double v,
                      SurfaceSample& at) {
  const glm::dvec2 start(u, v), shift(sun.x / sun.y, sun.z / sun.y);
  glm::dvec2 p = start;
  for (int k = 0; k < 12; ++k) {
    at = water.sample(p.x, p.y);
    const glm::dvec2 g = p - start - shift * at.height;
    if (glm::length(g) < 1e-7) return glm::dvec3(p.x, at.height, p.y);
    // J = I - shift (dh/dx, dh/dz)^T; its inverse by Sherman-Morrison.
    const glm::dvec2 slope(at.slopeX, at.slopeZ);
    const double denominator = 1.0 - glm::dot(slope, shift);
    if (!(std::abs(denominator) > 1e-3)) break;
    p -= g + shift * (glm::dot(slope, g) / denominator);
  }
  return sunRayHitsSurface(water, sun, u, v, at);
}

// For every pixel, a search radius (pixels) that covers every kernel reaching it: the largest
// per-pixel reach within the largest reach (a separable sliding maximum; conservative).
std::vector<int> searchWindows(const std::vector<int>& reach, int width, int height) {
  const int radius = reach.empty() ? 0 : *std::max_element(reach.begin(), reach.end());
  std::vector<int> rows(reach.size(), 0), out(reach.size(), 0);
  auto at = [width](int x, int y) { return static_cast<size_t>(y) * width + x; };
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      for (int k = std::max(x - radius, 0); k <= std::min(x + radius, width - 1); ++k)
        rows[at(x, y)] = std::max(rows[at(x, y)], reach[at(k, y)]);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      for (int k = std::max(y - radius, 0); k <= std::min(y + radius, height - 1); ++k)
        out[at(x, y)] = std::max(out[at(x, y)], rows[at(x, k)]);
  return out;
}

// The pixels that gather one kind of light (the refracted under the water, the reflected above
// it) and their kernels.
struct Kernels {
  std::vector<double> radiusSquared;  // per pixel, 0 = gathers none of it
  // Per pixel: how many pixels around a photon projected there can hold it in their kernel.
  std::vector<int> window;
  // Per pixel, 1 / the share of the kernel's weight on the part of its disc where this light can
  // land (kernelShareAboveLevel); empty: all of it everywhere.
  std::vector<double> scale;
};

struct Frame {
  const Surface& water;
  const EmbreeScene& scene;
  const FrameReceivers& receivers;
  const FrameTraceDesc& desc;
  glm::dvec3 sun;
  glm::dvec3 up;  // unperturbed refracted sun reversed (receiver -> surface)
  double flatTransmittance = 1.0;
  Kernels seabed;  // the receivers under the water
  SunDisc disc{glm::dvec3(0.0, 1.0, 0.0), 0.0};
  CasterPathDesc casterPath;
  // Reflected light: the receivers above the water, l_r (receiver -> water under flat water)
  // and flat water's reflectance at the sun's incidence.
  Kernels mirror;
  glm::dvec3 mirrorDown{0.0, -1.0, 0.0};
  double flatReflectance = 1.0;
};

// A photon of `weight` (per channel) landing at x on a surface of normal `normal`: added to
// the kernel sums (Channels per pixel) of every pixel of `kernels` whose kernel holds it.
template <int Channels>
void splat(const Frame& f, const Kernels& kernels, const glm::dvec3& x, const glm::dvec3& normal,
           const double* weight, std::int64_t* sums) {
  const FrameReceivers& r = f.receivers;
  glm::dvec2 pixel;
  if (!r.project(x, pixel)) return;
  const int cx = static_cast<int>(std::floor(pixel.x)), cy = static_cast<int>(std::floor(pixel.y));
  if (cx < -64 || cy < -64 || cx >= r.width + 64 || cy >= r.height + 64) return;
  const int w0 = kernels.window[static_cast<size_t>(std::clamp(cy, 0, r.height - 1)) * r.width +
                                std::clamp(cx, 0, r.width - 1)];
  const int x0 = std::max(cx - w0, 0), x1 = std::min(cx + w0, r.width - 1);
  const int y0 = std::max(cy - w0, 0), y1 = std::min(cy + w0, r.height - 1);
  for (int py = y0; py <= y1; ++py) {
    for (int px = x0; px <= x1; ++px) {
      const size_t i = static_cast<size_t>(py) * r.width + px;
      const double r2 = kernels.radiusSquared[i];
      if (!(r2 > 0.0)) continue;
      const glm::dvec3 d = x - r.position[i];
      const double d2 = glm::dot(d, d);
      if (!(d2 < r2) || glm::dot(normal, r.normal[i]) < kMinNormalAgreement) continue;
      double k = (2.0 / (kPi * r2)) * (1.0 - d2 / r2);
      if (!kernels.scale.empty()) k *= kernels.scale[i];
      for (int c = 0; c < Channels; ++c)
        sums[i * Channels + static_cast<size_t>(c)] += std::llround(weight[c] * k * kSumScale);
    }
  }
}

// A sunlit photon of horizontal beam area `cellWeight` that met the water at `entry` (world x,
// z; height above the level) where the normal is `normal`: mirrored there, weighted by the
// reflectance relative to flat water's, and splatted where it first lands on a face turned
// toward it (mirrored again by any wave it runs into first).
void reflectPhoton(const Frame& f, const glm::dvec3& sunRay, const glm::dvec3& entry,
                   const glm::dvec3& normal, double cosIncident, double cellWeight,
                   Accumulator& acc) {
  const FrameReceivers& r = f.receivers;
  const double levelRelative = r.level - r.camera.y;
  double w = cellWeight * fresnelReflectance(cosIncident, f.desc.ior) / f.flatReflectance;
  glm::dvec3 at = entry;
  glm::dvec3 dir = glm::reflect(-sunRay, normal);
  for (int bounce = 0;; ++bounce) {
    const WaterCrossing again = nextWaterCrossing(f.water, at, dir);
    if (again.kind == WaterCrossing::Kind::Lost) {
      ++acc.mirrorIntoWater;
      return;
    }
    const bool meets = again.kind == WaterCrossing::Kind::Meets;
    const glm::dvec3 from(at.x - r.camera.x, levelRelative + at.y, at.z - r.camera.z);
    RayHit hit;
    if (f.scene.intersect(from, dir, 0.0, meets ? again.t : 1e30, hit)) {
      if (glm::dot(dir, hit.normal) < 0.0) {  // a face turned away absorbs it
        const double weight[1] = {w};
        splat<1>(f, f.mirror, from + dir * hit.t, hit.normal, weight, acc.reflected.data());
      }
      return;
    }
    if (!meets) return;  // up into the sky
    if (bounce + 1 >= kMaxMirrorBounces) {
      ++acc.mirrorIntoWater;
      return;
    }
    // A later wave: its reflected share goes on, the rest enters the water (not followed here).
    at += dir * again.t;
    const SurfaceSample s = f.water.sample(at.x, at.z);
    const glm::dvec3 n = glm::normalize(glm::dvec3(-s.slopeX, 1.0, -s.slopeZ));
    const double cosAgain = -glm::dot(dir, n);
    if (!(cosAgain > 0.0)) {
      ++acc.mirrorIntoWater;
      return;
    }
    if (bounce == 0) ++acc.mirrorRebounds;
    w *= fresnelReflectance(cosAgain, f.desc.ior);
    dir = glm::reflect(dir, n);
  }
}

// One cell's photons of one batch along `path`, splatted into `acc`. The reflected launch draws
// from streams of its own: the refracted one's photons are the same with or without it.
void traceCell(const Frame& f, const PhotonLaunchPlan& plan, PhotonPath path, int batch, int cellX,
               int cellZ, Accumulator& acc) {
  const size_t cell = static_cast<size_t>(cellZ) * plan.columns + cellX;
  const double need = plan.need[cell];
  if (!(need > 0.0)) return;
  const bool mirror = path == PhotonPath::Reflected;
  postfx::water::GaussianRandom random(
      (f.desc.seed * 0x9E3779B97F4A7C15ull) ^ (static_cast<std::uint64_t>(batch) << 40) ^
      (cell * 0xD1B54A32D192ED03ull) ^ (mirror ? kMirrorStream : 0ull));
  random.nextBits();
  // n x n strata, or one photon with probability `need` (weight 1 / need) where less than one
  // is needed.
  const int n = need >= 1.0 ? static_cast<int>(std::ceil(std::sqrt(need))) : 1;
  if (need < 1.0 && random.nextUniform() > need) return;
  const double step = plan.cellSize / n;
  const double cellWeight = need >= 1.0 ? step * step : step * step / need;
  const glm::dvec2 corner = plan.origin + glm::dvec2(cellX, cellZ) * plan.cellSize;
  const FrameReceivers& r = f.receivers;
  const double levelRelative = r.level - r.camera.y;
  const std::function<void(const CasterLanding&)> land = [&f, &acc](const CasterLanding& l) {
    const double weight[3] = {l.weight.x, l.weight.y, l.weight.z};
    splat<3>(f, f.seabed, l.point, l.normal, weight, acc.object.data());
  };
  for (int a = 0; a < n; ++a) {
    for (int b = 0; b < n; ++b) {
      const double u = corner.x + (a + random.nextUniform()) * step;
      const double v = corner.y + (b + random.nextUniform()) * step;
      SurfaceSample at;
      glm::dvec3 sunRay = f.sun;
      if (f.disc.angularRadius() > 0.0) {  // a point sun draws nothing: its rays stay as they were
        const double d1 = random.nextUniform();
        sunRay = f.disc.direction(d1, random.nextUniform());
      }
      const glm::dvec3 entry = entryPoint(f.water, sunRay, u, v, at);
      const glm::dvec3 normal = glm::normalize(glm::dvec3(-at.slopeX, 1.0, -at.slopeZ));
      const double cosIncident = glm::dot(sunRay, normal);
      if (!(cosIncident > 0.0)) {  // the back of a wave: no light enters or is reflected here
        ++(mirror ? acc.mirrorBackOfWave : acc.backOfWave);
        continue;
      }
      if (mirror) {
        const glm::dvec3 from(entry.x - r.camera.x, levelRelative + entry.y, entry.z - r.camera.z);
        if (f.scene.boundsMax().y > from.y && f.scene.occluded(from, sunRay, 0.0, 1e30)) continue;
        reflectPhoton(f, sunRay, entry, normal, cosIncident, cellWeight, acc);
        continue;
      }
      const glm::dvec3 dir = refractSunRay(sunRay, at.slopeX, at.slopeZ, f.desc.ior);
      if (!(dir.y < 0.0)) continue;
      const double w =
          cellWeight * fresnelTransmittance(cosIncident, f.desc.ior) / f.flatTransmittance;
      const glm::dvec3 from(entry.x - r.camera.x, levelRelative + entry.y, entry.z - r.camera.z);
      if (f.scene.boundsMax().y > from.y && f.scene.occluded(from, sunRay, 0.0, 1e30)) continue;
      RayHit hit;
      if (!f.scene.intersect(from, dir, 0.0, 1e30, hit)) continue;
      if (!(glm::dot(dir, hit.normal) < 0.0)) continue;  // a face turned away absorbs it
      const glm::dvec3 x = from + dir * hit.t;
      const double weight[1] = {w};
      splat<1>(f, f.seabed, x, hit.normal, weight, acc.sum.data());
      if (isCaster(f.desc.casters, hit.mesh))
        followThroughCasters(f.scene, f.desc.casters, f.casterPath, from, dir, hit, glm::dvec3(w),
                             random, land);
    }
  }
}

// Metres of the segment a -> b below the water level (camera-relative heights).
double wetLength(const Frame& f, const glm::dvec3& a, const glm::dvec3& b) {
  const double level = f.casterPath.waterLevel;
  return double(postfx::shared::submergedLength(static_cast<float>(glm::length(b - a)),
                                                static_cast<float>(a.y - level),
                                                static_cast<float>(b.y - level)));
}

// One row of a light cap's strata of one batch: photons that meet the cap's own caster first
// go on through the casters; what lands under the water is splatted into acc.local.
void traceLightRow(const Frame& f, const LightCap& cap, int batch, int row, Accumulator& acc) {
  postfx::water::GaussianRandom random((f.desc.seed * 0x9E3779B97F4A7C15ull) ^
                                       (static_cast<std::uint64_t>(batch) << 40) ^
                                       ((cap.index + 1) * 0xA24BAED4963EE407ull) ^
                                       (static_cast<std::uint64_t>(row) * 0xD1B54A32D192ED03ull));
  random.nextBits();
  const int n = cap.strata;
  const double photonAngle = cap.solidAngle / (double(n) * double(n));
  const TracedLight& light = *cap.light;
  glm::dvec3 entry(0.0);
  const std::function<void(const CasterLanding&)> land = [&](const CasterLanding& l) {
    if (!(l.point.y < f.casterPath.waterLevel)) return;  // its light stays under the water
    const double wet = wetLength(f, cap.position, entry) + wetLength(f, l.from, l.point);
    const glm::dvec3 w = l.weight * glm::exp(-f.desc.waterAbsorption * wet);
    const double weight[3] = {w.x, w.y, w.z};
    splat<3>(f, f.seabed, l.point, l.normal, weight, acc.local.data());
  };
  for (int i = 0; i < n; ++i) {
    const double cosTheta = 1.0 - (row + random.nextUniform()) / n * (1.0 - cap.cosHalf);
    const double sinTheta = std::sqrt(std::max(1.0 - cosTheta * cosTheta, 0.0));
    const double phi = 2.0 * kPi * (i + random.nextUniform()) / n;
    const glm::dvec3 dir =
        cap.axis * cosTheta + (cap.u * std::cos(phi) + cap.v * std::sin(phi)) * sinTheta;
    const double spot = spotFactor(light, dir);
    if (!(spot > 0.0)) continue;
    RayHit hit;
    if (!f.scene.intersect(cap.position, dir, 0.0, 1e30, hit) || hit.mesh != cap.mesh) continue;
    entry = cap.position + dir * hit.t;
    followThroughCasters(f.scene, f.desc.casters, f.casterPath, cap.position, dir, hit,
                         light.intensity * (spot * photonAngle), random, land);
  }
}

// Flat-water sunlight reaches receiver i: nothing on the unperturbed refracted ray up to the
// water plane, nor above the water toward the sun.
bool litByFlatWater(const Frame& f, size_t i) {
  const FrameReceivers& r = f.receivers;
  const glm::dvec3& q = r.position[i];
  const glm::dvec3& n = r.normal[i];
  if (!(glm::dot(n, f.up) > 0.0)) return false;
  const double offset = std::max(1e-3, 1e-4 * glm::length(q));
  const glm::dvec3 from = q + n * offset;
  const double toSurface = (r.level - r.camera.y - from.y) / f.up.y;
  if (toSurface > 0.0 && f.scene.occluded(from, f.up, 0.0, toSurface)) return false;
  const glm::dvec3 atSurface = from + f.up * std::max(toSurface, 0.0);
  return !(f.scene.boundsMax().y > atSurface.y && f.scene.occluded(atSurface, f.sun, 0.0, 1e30));
}

// Flat water's mirror light reaches receiver i (above the level): it faces l_r, nothing lies on
// the mirror ray down from it to the level, and the water point there is sunlit.
bool litByFlatMirror(const Frame& f, size_t i) {
  const FrameReceivers& r = f.receivers;
  const glm::dvec3& q = r.position[i];
  const glm::dvec3& n = r.normal[i];
  if (!(glm::dot(n, f.mirrorDown) > 0.0)) return false;
  const glm::dvec3 from = q + n * std::max(1e-3, 1e-4 * glm::length(q));
  const double toWater = (r.level - r.camera.y - from.y) / f.mirrorDown.y;
  if (toWater > 0.0 && f.scene.occluded(from, f.mirrorDown, 0.0, toWater)) return false;
  const glm::dvec3 atWater = from + f.mirrorDown * std::max(toWater, 0.0);
  return !(f.scene.boundsMax().y > atWater.y && f.scene.occluded(atWater, f.sun, 0.0, 1e30));
}

// Under flat water the light reaching receiver i passes through a caster first: the unperturbed
// refracted ray up from it meets a caster before the water plane.
bool inCasterShadow(const Frame& f, size_t i) {
  const FrameReceivers& r = f.receivers;
  const glm::dvec3& q = r.position[i];
  const glm::dvec3& n = r.normal[i];
  if (!(glm::dot(n, f.up) > 0.0)) return false;
  const glm::dvec3 from = q + n * std::max(1e-3, 1e-4 * glm::length(q));
  const double toSurface = (r.level - r.camera.y - from.y) / f.up.y;
  RayHit hit;
  return toSurface > 0.0 && f.scene.intersect(from, f.up, 0.0, toSurface, hit) &&
         isCaster(f.desc.casters, hit.mesh);
}

// A receiver's kernel radius (m) and how many pixels from it a photon in its kernel can project.
struct KernelSize {
  double radius = 0.0;
  int reach = 0;
};

KernelSize kernelSize(const FrameReceivers& receivers, size_t i, const FrameTraceDesc& desc,
                      double rpp) {
  const glm::dvec3& q = receivers.position[i];
  const glm::dvec3& n = receivers.normal[i];
  const double distance = glm::length(q);
  const double facing = distance > 0.0 ? std::abs(glm::dot(n, q)) / distance : 1.0;
  const double radius =
      std::max(desc.kernelScale * distance * rpp / std::sqrt(std::max(facing, 1.0 / 16.0)),
               desc.minKernelRadius);
  // A photon within r_i of q_i projects at most r_i / (|q_i| rpp) pixels (+1 for the pixel
  // centre) from pixel i; the area-matched radius keeps that below 4 kernelScale.
  const int reach =
      static_cast<int>(std::ceil(std::min(radius / std::max(distance * rpp, 1e-12), 64.0))) + 1;
  return {radius, reach};
}

// Photons per square metre of the water plane a kernel of `radius` receiving `flat` (its light
// under flat water, in photons' units) needs.
double launchDensity(const FrameTraceDesc& desc, double radius, double flat) {
  double density =
      desc.kernelPhotonsPerBatch / (kPi * radius * radius * std::max(flat, kNoiseFloor));
  // Where that is under one photon per cell, the cell launches single photons at random:
  // plain Poisson counting, without the several-fold gain of stratification. Such kernels
  // (large, far away) get more photons, up to one per cell, so that they converge with the
  // stratified ones instead of setting the number of batches.
  const double cellArea = desc.cellSize * desc.cellSize;
  if (density * cellArea < 1.0) density = std::min(density * desc.sparseBoost, 1.0 / cellArea);
  return density;
}

// The share of an Epanechnikov kernel's weight (radius r, on the plane of normal n through a
// point `height` above the level) that lies above the level, where the water's reflected light
// lands: a wall's or a hull's kernel at the waterline would otherwise count the part of its
// disc under the water as dark. The plane meets the level along a line d = height / |n x y|
// from the centre; the kernel's marginal across that line is (8 / 3 pi) (1 - x^2)^(3/2) for
// x = t / r, whose integral from -d / r to 1 is
//     1/2 + (8 / 3 pi) [x (1 - x^2)^(3/2) / 4 + 3 x sqrt(1 - x^2) / 8 + 3 asin(x) / 8] at x = d/r.
double kernelShareAboveLevel(const glm::dvec3& n, double height, double r) {
  const double slant = std::sqrt(std::max(1.0 - n.y * n.y, 0.0));
  if (!(height < r * slant)) return 1.0;  // the disc stays above the level
  const double x = std::clamp(height / (r * slant), 0.0, 1.0);
  const double root = std::sqrt(1.0 - x * x);
  return 0.5 + 8.0 / (3.0 * kPi) *
                   (x * root * root * root / 4.0 + 3.0 * x * root / 8.0 + 3.0 * std::asin(x) / 8.0);
}

// The receivers above the level (reflected light): their kernels into f.mirror, kernel radii
// and flat mirror light into `result`, and where on the water plane their light comes from.
// A photon launched at u (the sun ray's crossing of the mean plane) meets the water at height
// eta at u + s eta (s = sun.xz / sun.y) and rises from there with the drift L per metre of rise
// of its reflected ray, landing at p (height h_p) when u = p.xz - L (h_p - eta) - s eta. With L
// within rho of c (mirrorDrift), |eta| <= H and p on the kernel disc of radius r around the
// receiver q (height h):
//     |u - (q.xz - c h)| <= rho (h + r + H) + (|c| + |s|) H + r (1 + |c|).
// Flat water: c = -s, rho = 0, the sun's mirror point h s toward the sun. Taken 5 % wider (the
// drift is sampled, not solved).
std::vector<LaunchNeed> planMirrorReceivers(Frame& f, double rpp, FrameTraceResult& result) {
  const FrameReceivers& receivers = f.receivers;
  const FrameTraceDesc& desc = f.desc;
  const size_t count = receivers.size();
  const double maxHeight = f.water.maxHeight();
  const double s = glm::length(glm::dvec2(f.sun.x, f.sun.z)) / f.sun.y;
  const MirrorDrift drift =
      mirrorDrift(f.sun, f.water.maxSlope() + std::tan(desc.sunAngularRadius));
  const double c = glm::length(drift.centre);
  f.mirror.radiusSquared.assign(count, 0.0);
  f.mirror.scale.assign(count, 1.0);
  std::vector<int> reach(count, 0);
  std::vector<LaunchNeed> needs;
  for (size_t i = 0; i < count; ++i) {
    if (!receivers.above[i]) continue;
    const KernelSize kernel = kernelSize(receivers, i, desc, rpp);
    result.kernelRadius[i] = kernel.radius;
    f.mirror.radiusSquared[i] = kernel.radius * kernel.radius;
    reach[i] = kernel.reach;
    const glm::dvec3& n = receivers.normal[i];
    result.flatReflected[i] = std::max(glm::dot(n, f.mirrorDown), 0.0) / -f.mirrorDown.y;
    f.mirror.scale[i] = 1.0 / kernelShareAboveLevel(n, -receivers.depthBelow(i), kernel.radius);
    if (!mayReceiveMirrorLight(n, f.sun, f.water.maxSlope(), desc.sunAngularRadius)) continue;
    const double height = -receivers.depthBelow(i);
    const glm::dvec3& q = receivers.position[i];
    const glm::dvec2 world(q.x + receivers.camera.x, q.z + receivers.camera.z);
    const double r = kernel.radius;
    const double extent =
        drift.radius * (height + r + maxHeight) + (c + s) * maxHeight + r * (1.0 + c);
    needs.push_back({world - drift.centre * height, 1.05 * extent + 1e-3,
                     launchDensity(desc, r, result.flatReflected[i])});
  }
  f.mirror.window = searchWindows(reach, receivers.width, receivers.height);
  return needs;
}

// A launch plan of at most `maxPhotons` per batch (thinned uniformly above it).
PhotonLaunchPlan planLaunch(const std::vector<LaunchNeed>& needs, const FrameTraceDesc& desc) {
  PhotonLaunchPlan plan = planPhotonLaunch(needs, desc.cellSize);
  if (plan.photons() > static_cast<double>(desc.maxPhotonsPerBatch)) {
    const double thin = static_cast<double>(desc.maxPhotonsPerBatch) / plan.photons();
    for (double& n : plan.need) n *= thin;
  }
  return plan;
}

// Per pixel, over batches, one kind of light's batch estimates: their sum and sum of squares
// (summed in batch order from the integer batch sums: deterministic).
struct BatchMoments {
  std::vector<double> sum, squares;
  void add(size_t i, double estimate) {
    sum[i] += estimate;
    squares[i] += estimate * estimate;
  }
  // Mean and standard error of the mean of `batches` independent estimates (their scatter).
  double mean(size_t i, double batches) const { return sum[i] / batches; }
  double standardError(size_t i, double batches) const {
    const double e = sum[i] / batches;
    const double variance =
        batches > 1.0 ? std::max(squares[i] - batches * e * e, 0.0) / (batches - 1.0) : 0.0;
    return std::sqrt(variance / batches);
  }
};

struct NoiseStatistics {
  double median = 0.0, quantile = 0.0, max = 0.0;
};

NoiseStatistics noiseStatistics(const std::vector<double>& noise, double q) {
  return {quantile(noise, 0.5), quantile(noise, q),
          noise.empty() ? 0.0 : *std::max_element(noise.begin(), noise.end())};
}

}  // namespace

FrameTraceResult traceFrameCaustics(const Surface& water, const EmbreeScene& scene,
                                    const FrameReceivers& receivers, const FrameTraceDesc& desc) {
  const auto start = std::chrono::steady_clock::now();
  FrameTraceResult result;
  const size_t count = receivers.size();
  result.irradiance.assign(count, 0.0);
  result.flatIrradiance.assign(count, 0.0);
  result.standardError.assign(count, 0.0);
  result.noise.assign(count, 0.0);
  result.kernelRadius.assign(count, 0.0);
  result.lit.assign(count, 0);
  if (count == 0 || receivers.position.size() != count) return result;
  // A sun below the horizon lights nothing; local lights may still shine through casters.
  const bool sunUp = glm::normalize(desc.towardSun).y > 0.0;
  const bool casters = !desc.casters.empty();
  const bool lights = casters && !desc.lights.empty();
  // Reflected light: sunlight only, onto the receivers above the level.
  const bool mirror = desc.reflected && sunUp && receivers.above.size() == count;
  if (desc.reflected) {
    result.reflectedIrradiance.assign(count, 0.0);
    result.flatReflected.assign(count, 0.0);
    result.reflectedStandardError.assign(count, 0.0);
    result.reflectedNoise.assign(count, 0.0);
    result.reflectedLit.assign(count, 0);
  }
  if (!sunUp && !lights) return result;
  const glm::dvec3 sun = sunUp ? glm::normalize(desc.towardSun) : glm::dvec3(0.0, 1.0, 0.0);

  Frame f{water, scene, receivers,         desc, sun, -refractSunRay(sun, 0.0, 0.0, desc.ior),
          1.0,   {},    SunDisc(sun, 0.0), {},   {},  flatMirrorDirection(sun),
          1.0};
  f.flatTransmittance = fresnelTransmittance(sun.y, desc.ior);
  f.disc = SunDisc(sun, sunUp ? desc.sunAngularRadius : 0.0);
  f.seabed.radiusSquared.assign(count, 0.0);
  f.casterPath.waterIor = desc.ior;
  f.casterPath.waterLevel = receivers.level - receivers.camera.y;
  f.flatReflectance = fresnelReflectance(sun.y, desc.ior);
  if (casters) {
    result.objectIrradiance.assign(count, glm::dvec3(0.0));
    result.casterShadow.assign(count, 0);
  }

  // Kernels, flat irradiance, lit mask and what each receiver needs from the launch.
  const double rpp = receivers.radiansPerPixel();
  const glm::dvec3 flatDown = -f.up;
  const glm::dvec2 drift(flatDown.x / -flatDown.y, flatDown.z / -flatDown.y);
  // The sun's disc moves a ray less than a slope of its angular radius would (the refraction
  // shrinks it by 1/n): counted as one.
  const double slopeDrift =
      maxSlopeDrift(sun, desc.ior, water.maxSlope() + std::tan(desc.sunAngularRadius));
  const double heightDrift =
      (std::hypot(sun.x, sun.z) / sun.y + glm::length(drift)) * water.maxHeight();
  std::vector<LaunchNeed> needs;
  std::vector<int> reach(count, 0);
  for (size_t i = 0; i < count; ++i) {
    if (!receivers.valid[i]) continue;
    const glm::dvec3& q = receivers.position[i];
    const glm::dvec3& n = receivers.normal[i];
    const KernelSize kernel = kernelSize(receivers, i, desc, rpp);
    const double radius = kernel.radius;
    result.kernelRadius[i] = radius;
    f.seabed.radiusSquared[i] = radius * radius;
    reach[i] = kernel.reach;
    if (!sunUp) continue;
    result.flatIrradiance[i] = std::max(glm::dot(n, f.up), 0.0) / f.up.y;
    const double depth = receivers.depthBelow(i);
    const glm::dvec2 world(q.x + receivers.camera.x, q.z + receivers.camera.z);
    // Light can land anywhere on the kernel disc, which spans r horizontally and r in depth.
    const double kernelReach = radius * (1.0 + glm::length(drift) + slopeDrift);
    needs.push_back({world - drift * depth,
                     slopeDrift * (depth + water.maxHeight()) + heightDrift + kernelReach + 1e-3,
                     launchDensity(desc, radius, result.flatIrradiance[i])});
  }
  f.seabed.window = searchWindows(reach, receivers.width, receivers.height);
  const std::vector<LaunchNeed> mirrorNeeds =
      mirror ? planMirrorReceivers(f, rpp, result) : std::vector<LaunchNeed>{};
  {
    std::vector<std::thread> threads;
    const int threadCount = std::max(1, desc.threads);
    for (int t = 0; t < threadCount; ++t) {
      threads.emplace_back([&, t] {
        for (size_t i = static_cast<size_t>(t); i < count; i += static_cast<size_t>(threadCount)) {
          if (receivers.valid[i] && sunUp) {
            result.lit[i] = litByFlatWater(f, i) ? 1 : 0;
            if (casters && !result.lit[i]) result.casterShadow[i] = inCasterShadow(f, i) ? 1 : 0;
          }
          if (mirror && receivers.above[i]) result.reflectedLit[i] = litByFlatMirror(f, i) ? 1 : 0;
        }
      });
    }
    for (std::thread& thread : threads) thread.join();
  }
  for (size_t i = 0; i < count; ++i) result.litPixels += result.lit[i];
  for (std::uint8_t l : result.reflectedLit) result.reflectedLitPixels += l;

  // Local lights: each pixel's direct light from them (the unit of their noise), the casters'
  // shadows in it, and one stratified cone of photons per light and caster.
  std::vector<LightCap> caps;
  std::vector<double> localUnit;
  if (lights) {
    result.localIrradiance.assign(count, glm::dvec3(0.0));
    caps = planLightCaps(scene, receivers, desc, f.seabed.radiusSquared, result.localDirect,
                         result.casterShadow, localUnit, result.localDirectMedian);
    for (const LightCap& cap : caps)
      result.lightPhotonsPerBatch += static_cast<std::uint64_t>(cap.strata) * cap.strata;
  }
  for (std::uint8_t s : result.casterShadow) result.casterShadowPixels += s;

  const PhotonLaunchPlan plan = sunUp ? planLaunch(needs, desc) : PhotonLaunchPlan{};
  const PhotonLaunchPlan mirrorPlan =
      !mirrorNeeds.empty() ? planLaunch(mirrorNeeds, desc) : PhotonLaunchPlan{};
  result.reflectedPhotonsPerBatch = static_cast<std::uint64_t>(std::llround(mirrorPlan.photons()));
  const auto perBatch = static_cast<std::uint64_t>(std::llround(plan.photons())) +
                        result.lightPhotonsPerBatch + result.reflectedPhotonsPerBatch;
  result.photonsPerBatch = perBatch;

  const int threadCount = std::max(1, desc.threads);
  // Per pixel, over batches: the batch estimates of the light under the water (seabed, plus
  // the mean object light and the local lights' in their units) and of the reflected light.
  BatchMoments moments{std::vector<double>(count, 0.0), std::vector<double>(count, 0.0)};
  BatchMoments mirrorMoments{std::vector<double>(mirror ? count : 0, 0.0),
                             std::vector<double>(mirror ? count : 0, 0.0)};
  // With casters, apart: the seabed estimate's and the object light's sums.
  std::vector<double> seabedSum(casters ? count : 0, 0.0);
  std::vector<glm::dvec3> objectSum(casters ? count : 0, glm::dvec3(0.0));
  std::vector<glm::dvec3> localSum(lights ? count : 0, glm::dvec3(0.0));
  Accumulator batchTotal;
  std::vector<Accumulator> partial(static_cast<size_t>(threadCount));
  std::vector<double> litNoise, mirrorNoise;
  for (int batch = 0; batch < std::max(desc.maxBatches, 1); ++batch) {
    std::vector<std::thread> threads;
    for (int t = 0; t < threadCount; ++t) {
      partial[static_cast<size_t>(t)].reset(count, casters, lights, mirror);
      threads.emplace_back([&, t] {
        Accumulator& acc = partial[static_cast<size_t>(t)];
        for (int row = t; row < plan.rows; row += threadCount)
          for (int column = 0; column < plan.columns; ++column)
            traceCell(f, plan, PhotonPath::Refracted, batch, column, row, acc);
        for (int row = t; row < mirrorPlan.rows; row += threadCount)
          for (int column = 0; column < mirrorPlan.columns; ++column)
            traceCell(f, mirrorPlan, PhotonPath::Reflected, batch, column, row, acc);
        for (const LightCap& cap : caps)
          for (int row = t; row < cap.strata; row += threadCount)
            traceLightRow(f, cap, batch, row, acc);
      });
    }
    for (std::thread& thread : threads) thread.join();
    batchTotal.reset(count, casters, lights, mirror);
    for (const Accumulator& p : partial) {
      for (size_t i = 0; i < count; ++i) batchTotal.sum[i] += p.sum[i];
      for (size_t k = 0; k < p.object.size(); ++k) batchTotal.object[k] += p.object[k];
      for (size_t k = 0; k < p.local.size(); ++k) batchTotal.local[k] += p.local[k];
      for (size_t k = 0; k < p.reflected.size(); ++k) batchTotal.reflected[k] += p.reflected[k];
      result.backOfWavePhotons += p.backOfWave;
      result.reflectedBackOfWavePhotons += p.mirrorBackOfWave;
      result.reflectedIntoWaterPhotons += p.mirrorIntoWater;
      result.reflectedReboundPhotons += p.mirrorRebounds;
    }
    for (size_t i = 0; i < count; ++i) {
      double estimate = static_cast<double>(batchTotal.sum[i]) / kSumScale;
      if (casters) {
        const glm::dvec3 object(static_cast<double>(batchTotal.object[3 * i]),
                                static_cast<double>(batchTotal.object[3 * i + 1]),
                                static_cast<double>(batchTotal.object[3 * i + 2]));
        seabedSum[i] += estimate;
        objectSum[i] += object / kSumScale;
        estimate += (object.x + object.y + object.z) / (3.0 * kSumScale);
      }
      if (lights) {
        const glm::dvec3 local(static_cast<double>(batchTotal.local[3 * i]),
                               static_cast<double>(batchTotal.local[3 * i + 1]),
                               static_cast<double>(batchTotal.local[3 * i + 2]));
        localSum[i] += local / kSumScale;
        // In units of the lights' direct light here, as the sun's is in flat water's.
        estimate += (local.x + local.y + local.z) / (3.0 * kSumScale * localUnit[i]);
      }
      moments.add(i, estimate);
      if (mirror) mirrorMoments.add(i, static_cast<double>(batchTotal.reflected[i]) / kSumScale);
    }
    result.batches = batch + 1;
    result.photons += perBatch;
    const double batches = result.batches;
    litNoise.clear();
    mirrorNoise.clear();
    for (size_t i = 0; i < count; ++i) {
      if (mirror && receivers.above[i]) {
        const double e = mirrorMoments.mean(i, batches);
        const double se = mirrorMoments.standardError(i, batches);
        result.reflectedIrradiance[i] = e;
        result.reflectedStandardError[i] = se;
        result.reflectedNoise[i] = se / std::max({e, result.flatReflected[i], kNoiseFloor});
        if (result.reflectedLit[i]) mirrorNoise.push_back(result.reflectedNoise[i]);
      }
      if (!receivers.valid[i]) continue;
      const double e = moments.mean(i, batches);  // seabed + mean object light
      const double se = moments.standardError(i, batches);
      result.irradiance[i] = e;
      if (casters) {
        result.irradiance[i] = seabedSum[i] / batches;
        result.objectIrradiance[i] = objectSum[i] / batches;
      }
      if (lights) result.localIrradiance[i] = localSum[i] / batches;
      result.standardError[i] = se;
      result.noise[i] = se / std::max({e, result.flatIrradiance[i], kNoiseFloor});
      if (result.lit[i] || (casters && result.casterShadow[i])) litNoise.push_back(result.noise[i]);
    }
    const NoiseStatistics mirrorStats = noiseStatistics(mirrorNoise, desc.noiseQuantile);
    result.reflectedNoiseMedian = mirrorStats.median;
    result.reflectedNoiseQuantile = mirrorStats.quantile;
    result.reflectedNoiseMax = mirrorStats.max;
    // The reflected light's noise decides convergence with the rest.
    litNoise.insert(litNoise.end(), mirrorNoise.begin(), mirrorNoise.end());
    const NoiseStatistics stats = noiseStatistics(litNoise, desc.noiseQuantile);
    result.noiseMedian = stats.median;
    result.noiseQuantile = stats.quantile;
    result.noiseMax = stats.max;
    result.converged =
        result.batches >= std::max(desc.minBatches, 2) && result.noiseQuantile < desc.targetNoise;
    result.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const bool done = result.converged || result.batches >= desc.maxBatches;
    if (desc.progress) {
      FrameTraceProgress progress;
      progress.batch = result.batches;
      progress.photons = result.photons;
      progress.noiseMedian = result.noiseMedian;
      progress.noiseQuantile = result.noiseQuantile;
      progress.noiseMax = result.noiseMax;
      progress.reflected = mirror;
      progress.reflectedLitPixels = result.reflectedLitPixels;
      progress.reflectedNoiseMedian = result.reflectedNoiseMedian;
      progress.reflectedNoiseQuantile = result.reflectedNoiseQuantile;
      progress.reflectedNoiseMax = result.reflectedNoiseMax;
      progress.seconds = result.seconds;
      progress.done = done;
      progress.converged = result.converged;
      desc.progress(progress);
    }
    if (done) break;
  }
  return result;
}

}  // namespace ocean::reference
