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

struct Accumulator {
  std::vector<std::int64_t> sum;
  std::vector<std::int64_t> object;  // 3 per pixel (RGB), with casters only
  std::vector<std::int64_t> local;   // 3 per pixel (RGB), with traced local lights only
  void reset(size_t n, bool casters, bool lights) {
    sum.assign(n, 0);
    object.assign(casters ? 3 * n : 0, 0);
    local.assign(lights ? 3 * n : 0, 0);
  }
};

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

struct Frame {
  const Surface& water;
  const EmbreeScene& scene;
  const FrameReceivers& receivers;
  const FrameTraceDesc& desc;
  glm::dvec3 sun;
  glm::dvec3 up;  // unperturbed refracted sun reversed (receiver -> surface)
  double flatTransmittance = 1.0;
  std::vector<double> radiusSquared;  // per pixel, 0 = not a receiver
  // Per pixel: how many pixels around a photon projected there can hold it in their kernel.
  std::vector<int> window;
  SunDisc disc{glm::dvec3(0.0, 1.0, 0.0), 0.0};
  CasterPathDesc casterPath;
};

// A photon of `weight` (per channel) landing at x on a surface of normal `normal`: added to
// the kernel sums (Channels per pixel) of every pixel whose kernel holds it.
template <int Channels>
void splat(const Frame& f, const glm::dvec3& x, const glm::dvec3& normal, const double* weight,
           std::int64_t* sums) {
  const FrameReceivers& r = f.receivers;
  glm::dvec2 pixel;
  if (!r.project(x, pixel)) return;
  const int cx = static_cast<int>(std::floor(pixel.x)), cy = static_cast<int>(std::floor(pixel.y));
  if (cx < -64 || cy < -64 || cx >= r.width + 64 || cy >= r.height + 64) return;
  const int w0 = f.window[static_cast<size_t>(std::clamp(cy, 0, r.height - 1)) * r.width +
                          std::clamp(cx, 0, r.width - 1)];
  const int x0 = std::max(cx - w0, 0), x1 = std::min(cx + w0, r.width - 1);
  const int y0 = std::max(cy - w0, 0), y1 = std::min(cy + w0, r.height - 1);
  for (int py = y0; py <= y1; ++py) {
    for (int px = x0; px <= x1; ++px) {
      const size_t i = static_cast<size_t>(py) * r.width + px;
      const double r2 = f.radiusSquared[i];
      if (!(r2 > 0.0)) continue;
      const glm::dvec3 d = x - r.position[i];
      const double d2 = glm::dot(d, d);
      if (!(d2 < r2) || glm::dot(normal, r.normal[i]) < kMinNormalAgreement) continue;
      const double k = (2.0 / (kPi * r2)) * (1.0 - d2 / r2);
      for (int c = 0; c < Channels; ++c)
        sums[i * Channels + static_cast<size_t>(c)] += std::llround(weight[c] * k * kSumScale);
    }
  }
}

// One cell's photons of one batch, splatted into `acc`.
void traceCell(const Frame& f, const PhotonLaunchPlan& plan, int batch, int cellX, int cellZ,
               Accumulator& acc) {
  const size_t cell = static_cast<size_t>(cellZ) * plan.columns + cellX;
  const double need = plan.need[cell];
  if (!(need > 0.0)) return;
  postfx::water::GaussianRandom random((f.desc.seed * 0x9E3779B97F4A7C15ull) ^
                                       (static_cast<std::uint64_t>(batch) << 40) ^
                                       (cell * 0xD1B54A32D192ED03ull));
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
    splat<3>(f, l.point, l.normal, weight, acc.object.data());
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
      if (!(cosIncident > 0.0)) continue;  // the back of a wave: no light enters here
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
      splat<1>(f, x, hit.normal, weight, acc.sum.data());
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
    splat<3>(f, l.point, l.normal, weight, acc.local.data());
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
  if (!sunUp && !lights) return result;
  const glm::dvec3 sun = sunUp ? glm::normalize(desc.towardSun) : glm::dvec3(0.0, 1.0, 0.0);

  Frame f{water, scene, receivers,         desc, sun, -refractSunRay(sun, 0.0, 0.0, desc.ior), 1.0,
          {},    {},    SunDisc(sun, 0.0), {}};
  f.flatTransmittance = fresnelTransmittance(sun.y, desc.ior);
  f.disc = SunDisc(sun, sunUp ? desc.sunAngularRadius : 0.0);
  f.radiusSquared.assign(count, 0.0);
  f.casterPath.waterIor = desc.ior;
  f.casterPath.waterLevel = receivers.level - receivers.camera.y;
  if (casters) {
    result.objectIrradiance.assign(count, glm::dvec3(0.0));
    result.casterShadow.assign(count, 0);
  }

  // Kernels, flat irradiance, lit mask and what each receiver needs from the launch.
  const double rpp = receivers.radiansPerPixel();
  const double kernelPhotons = desc.kernelPhotonsPerBatch;
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
    const double distance = glm::length(q);
    const double facing = distance > 0.0 ? std::abs(glm::dot(n, q)) / distance : 1.0;
    const double radius =
        std::max(desc.kernelScale * distance * rpp / std::sqrt(std::max(facing, 1.0 / 16.0)),
                 desc.minKernelRadius);
    result.kernelRadius[i] = radius;
    f.radiusSquared[i] = radius * radius;
    // A photon within r_i of q_i projects at most r_i / (|q_i| rpp) pixels (+1 for the pixel
    // centre) from pixel i; the area-matched radius keeps that below 4 kernelScale.
    reach[i] =
        static_cast<int>(std::ceil(std::min(radius / std::max(distance * rpp, 1e-12), 64.0))) + 1;
    if (!sunUp) continue;
    result.flatIrradiance[i] = std::max(glm::dot(n, f.up), 0.0) / f.up.y;
    const double depth = receivers.depthBelow(i);
    const glm::dvec2 world(q.x + receivers.camera.x, q.z + receivers.camera.z);
    // Light can land anywhere on the kernel disc, which spans r horizontally and r in depth.
    const double kernelReach = radius * (1.0 + glm::length(drift) + slopeDrift);
    double density =
        kernelPhotons / (kPi * radius * radius * std::max(result.flatIrradiance[i], kNoiseFloor));
    // Where that is under one photon per cell, the cell launches single photons at random:
    // plain Poisson counting, without the several-fold gain of stratification. Such kernels
    // (large, far away) get more photons, up to one per cell, so that they converge with the
    // stratified ones instead of setting the number of batches.
    const double cellArea = desc.cellSize * desc.cellSize;
    if (density * cellArea < 1.0) density = std::min(density * desc.sparseBoost, 1.0 / cellArea);
    needs.push_back({world - drift * depth,
                     slopeDrift * (depth + water.maxHeight()) + heightDrift + kernelReach + 1e-3,
                     density});
  }
  f.window = searchWindows(reach, receivers.width, receivers.height);
  std::vector<double> litNoise;
  {
    std::vector<std::thread> threads;
    const int threadCount = std::max(1, desc.threads);
    for (int t = 0; t < threadCount; ++t) {
      threads.emplace_back([&, t] {
        for (size_t i = static_cast<size_t>(t); i < count; i += static_cast<size_t>(threadCount))
          if (receivers.valid[i] && sunUp) {
            result.lit[i] = litByFlatWater(f, i) ? 1 : 0;
            if (casters && !result.lit[i]) result.casterShadow[i] = inCasterShadow(f, i) ? 1 : 0;
          }
      });
    }
    for (std::thread& thread : threads) thread.join();
  }
  for (size_t i = 0; i < count; ++i) result.litPixels += result.lit[i];

  // Local lights: each pixel's direct light from them (the unit of their noise), the casters'
  // shadows in it, and one stratified cone of photons per light and caster.
  std::vector<LightCap> caps;
  std::vector<double> localUnit;
  if (lights) {
    result.localIrradiance.assign(count, glm::dvec3(0.0));
    caps = planLightCaps(scene, receivers, desc, f.radiusSquared, result.localDirect,
                         result.casterShadow, localUnit, result.localDirectMedian);
    for (const LightCap& cap : caps)
      result.lightPhotonsPerBatch += static_cast<std::uint64_t>(cap.strata) * cap.strata;
  }
  for (std::uint8_t s : result.casterShadow) result.casterShadowPixels += s;

  PhotonLaunchPlan plan = sunUp ? planPhotonLaunch(needs, desc.cellSize) : PhotonLaunchPlan{};
  if (plan.photons() > static_cast<double>(desc.maxPhotonsPerBatch)) {
    const double thin = static_cast<double>(desc.maxPhotonsPerBatch) / plan.photons();
    for (double& n : plan.need) n *= thin;
  }
  const auto perBatch =
      static_cast<std::uint64_t>(std::llround(plan.photons())) + result.lightPhotonsPerBatch;
  result.photonsPerBatch = perBatch;

  const int threadCount = std::max(1, desc.threads);
  // Per pixel, over batches: the sum of the batch estimates and of their squares (summed in
  // batch order from the integer batch sums: deterministic).
  std::vector<double> sum(count, 0.0), squares(count, 0.0);
  // With casters, apart: the seabed estimate's and the object light's sums.
  std::vector<double> seabedSum(casters ? count : 0, 0.0);
  std::vector<glm::dvec3> objectSum(casters ? count : 0, glm::dvec3(0.0));
  std::vector<glm::dvec3> localSum(lights ? count : 0, glm::dvec3(0.0));
  Accumulator batchTotal;
  std::vector<Accumulator> partial(static_cast<size_t>(threadCount));
  for (int batch = 0; batch < std::max(desc.maxBatches, 1); ++batch) {
    std::vector<std::thread> threads;
    for (int t = 0; t < threadCount; ++t) {
      partial[static_cast<size_t>(t)].reset(count, casters, lights);
      threads.emplace_back([&, t] {
        for (int row = t; row < plan.rows; row += threadCount)
          for (int column = 0; column < plan.columns; ++column)
            traceCell(f, plan, batch, column, row, partial[static_cast<size_t>(t)]);
        for (const LightCap& cap : caps)
          for (int row = t; row < cap.strata; row += threadCount)
            traceLightRow(f, cap, batch, row, partial[static_cast<size_t>(t)]);
      });
    }
    for (std::thread& thread : threads) thread.join();
    batchTotal.reset(count, casters, lights);
    for (const Accumulator& p : partial) {
      for (size_t i = 0; i < count; ++i) batchTotal.sum[i] += p.sum[i];
      for (size_t k = 0; k < p.object.size(); ++k) batchTotal.object[k] += p.object[k];
      for (size_t k = 0; k < p.local.size(); ++k) batchTotal.local[k] += p.local[k];
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
      sum[i] += estimate;
      squares[i] += estimate * estimate;
    }
    result.batches = batch + 1;
    result.photons += perBatch;
    const double batches = result.batches;
    litNoise.clear();
    for (size_t i = 0; i < count; ++i) {
      if (!receivers.valid[i]) continue;
      const double e = sum[i] / batches;  // seabed + mean object light
      // Standard error of the mean of independent batch estimates, from their scatter.
      const double variance =
          batches > 1.0 ? std::max(squares[i] - batches * e * e, 0.0) / (batches - 1.0) : 0.0;
      const double se = std::sqrt(variance / batches);
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
    result.noiseMedian = quantile(litNoise, 0.5);
    result.noiseQuantile = quantile(litNoise, desc.noiseQuantile);
    result.noiseMax = litNoise.empty() ? 0.0 : *std::max_element(litNoise.begin(), litNoise.end());
    result.converged =
        result.batches >= std::max(desc.minBatches, 2) && result.noiseQuantile < desc.targetNoise;
    result.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const bool done = result.converged || result.batches >= desc.maxBatches;
    if (desc.progress) {
      desc.progress({result.batches, result.photons, result.noiseMedian, result.noiseQuantile,
                     result.noiseMax, result.seconds, done, result.converged});
    }
    if (done) break;
  }
  return result;
}

}  // namespace ocean::reference
