#include "seabed_reference.h"
#include "sun_disc.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <thread>

#include <postfx/water/random.h>

namespace ocean::reference {
namespace {

// Horizontal drift per metre of descent of a downward ray.
glm::dvec2 lateral(const glm::dvec3& down) {
  return glm::dvec2(down.x, down.z) / -down.y;
}

// Regula falsi (Illinois variant) for the root of f in [a, b] with f(a) >= 0 >= f(b).
template <class F>
double refineRoot(F f, double a, double fa, double b, double fb) {
  int side = 0;
  double c = 0.5 * (a + b);
  for (int i = 0; i < 100 && std::abs(b - a) > 1e-12 * (1.0 + std::abs(a)); ++i) {
    const double denom = fa - fb;
    c = denom != 0.0 ? (a * (-fb) + b * fa) / denom : 0.5 * (a + b);
    const double fc = f(c);
    if (fc == 0.0) return c;
    if (fc > 0.0) {
      a = c;
      fa = fc;
      if (side == 1) fb *= 0.5;
      side = 1;
    } else {
      b = c;
      fb = fc;
      if (side == -1) fa *= 0.5;
      side = -1;
    }
  }
  // The last estimate, not the bracket's midpoint: for a near-linear f one end of the bracket
  // converges onto the root while the other stays put.
  return c;
}

// First crossing (from t = tStart downwards to tEnd) of f from >= 0 to < 0, marching in steps
// of at most `step`. With f(tEnd) <= 0 there is one; otherwise returns `noCrossing`.
template <class F>
double firstCrossing(F f, double tStart, double tEnd, double step, double noCrossing) {
  double a = tStart, fa = f(a);
  if (fa < 0.0) return tStart;
  const double direction = tEnd < tStart ? -1.0 : 1.0;
  const int steps = std::max(1, static_cast<int>(std::ceil(std::abs(tEnd - tStart) / step)));
  for (int k = 1; k <= steps; ++k) {
    const double b = k == steps ? tEnd : tStart + direction * step * k;
    const double fb = f(b);
    if (fb < 0.0) return refineRoot(f, a, fa, b, fb);
    if (fb == 0.0) return b;
    a = b;
    fa = fb;
  }
  return noCrossing;
}

struct Accumulator {
  std::vector<std::vector<double>> sum, sumSquares;
  std::vector<std::vector<std::uint64_t>> hits;

  void reset(size_t receivers, size_t bins) {
    sum.assign(receivers, std::vector<double>(bins, 0.0));
    sumSquares.assign(receivers, std::vector<double>(bins, 0.0));
    hits.assign(receivers, std::vector<std::uint64_t>(bins, 0));
  }
  void add(const Accumulator& other) {
    for (size_t r = 0; r < sum.size(); ++r) {
      for (size_t i = 0; i < sum[r].size(); ++i) {
        sum[r][i] += other.sum[r][i];
        sumSquares[r][i] += other.sumSquares[r][i];
        hits[r][i] += other.hits[r][i];
      }
    }
  }
};

struct LaunchWindow {
  glm::dvec2 min{0.0}, max{0.0};
  double margin = 0.0;
};

// The region of the mean plane whose rays can reach the bins: the bin region moved back by the
// flat-water drift and widened by the largest drift the surface's heights and slopes can add.
LaunchWindow launchWindow(const Surface& surface, const ReferenceDesc& desc,
                          const glm::dvec3& sun) {
  const double maxHeight = surface.maxHeight(), maxSlope = surface.maxSlope();
  const glm::dvec2 flatDrift = lateral(refractSunRay(sun, 0.0, 0.0, desc.ior));
  // The sun's disc tilts a ray less than a slope of its angular radius would: counted as one.
  const double slopeDrift =
      maxSlopeDrift(sun, desc.ior, maxSlope + std::tan(desc.sunAngularRadius));
  const glm::dvec2 binMin = desc.bins.origin;
  const glm::dvec2 binMax =
      binMin + desc.bins.size() * glm::dvec2(desc.bins.countX, desc.bins.countZ);
  const double sunDrift = glm::length(glm::dvec2(sun.x, sun.z)) / sun.y;
  LaunchWindow w{glm::dvec2(1e300), glm::dvec2(-1e300), 0.0};
  for (const Receiver& receiver : desc.receivers) {
    const double lo = receiver.depthAt ? receiver.minDepth : receiver.depth;
    for (double depth : {lo, receiver.depth}) {
      const double margin = 1.05 * (sunDrift * maxHeight + glm::length(flatDrift) * maxHeight +
                                    slopeDrift * (depth + maxHeight)) +
                            1e-3;
      w.min = glm::min(w.min, binMin - flatDrift * depth - margin);
      w.max = glm::max(w.max, binMax - flatDrift * depth + margin);
      w.margin = std::max(w.margin, margin);
    }
  }
  return w;
}

struct Tracer {
  const Surface& surface;
  const ReferenceDesc& desc;
  glm::dvec3 sun;
  double flatTransmittance;
  double maxHeight;

  SunDisc disc;

  // Where the ray toward `ray` crossing the mean plane at (u, v) first meets the surface.
  bool hitSurface(const glm::dvec3& ray, double u, double v, glm::dvec3& point,
                  SurfaceSample& at) const {
    point = sunRayHitsSurface(surface, ray, u, v, at);
    return true;
  }

  // Parameter (in-water path length, |dir| = 1) at which `dir` from `point` meets `receiver`;
  // negative when it cannot (receiver above the surface point).
  double hitReceiver(const Receiver& receiver, const glm::dvec3& point,
                     const glm::dvec3& dir) const {
    if (!receiver.depthAt) return (-receiver.depth - point.y) / dir.y;
    auto aboveSeabed = [&](double t) {
      return point.y + dir.y * t + receiver.depthAt(point.x + dir.x * t, point.z + dir.z * t);
    };
    const double end = (receiver.depth + maxHeight + 1e-9) / -dir.y;
    const double horizontal = std::max(std::hypot(dir.x, dir.z), 1e-9);
    const double step = std::min(0.5 * receiver.featureSize / horizontal, end);
    if (aboveSeabed(0.0) < 0.0) return -1.0;
    // No crossing by `end` (only when depth does not bound depthAt, against its contract):
    // the ray misses rather than being binned where it stopped.
    return firstCrossing(aboveSeabed, 0.0, end, step, -1.0);
  }

  void traceRow(int batch, int row, const LaunchWindow& window, glm::dvec2 cell, int columns,
                Accumulator& acc) const {
    postfx::water::GaussianRandom random(0x5EABEDull ^ (static_cast<std::uint64_t>(batch) << 32) ^
                                         static_cast<std::uint64_t>(row) * 0x9E3779B97F4A7C15ull);
    const BinGrid& bins = desc.bins;
    const glm::dvec2 binSize = bins.size();
    const double weight = cell.x * cell.y;
    for (int column = 0; column < columns; ++column) {
      const double u = window.min.x + (column + random.nextUniform()) * cell.x;
      const double v = window.min.y + (row + random.nextUniform()) * cell.y;
      glm::dvec3 ray = sun;
      if (disc.angularRadius() > 0.0) {  // a point sun draws nothing: its rays stay as they were
        const double d1 = random.nextUniform();
        ray = disc.direction(d1, random.nextUniform());
      }
      glm::dvec3 point;
      SurfaceSample at;
      if (!hitSurface(ray, u, v, point, at)) continue;
      const glm::dvec3 normal = glm::normalize(glm::dvec3(-at.slopeX, 1.0, -at.slopeZ));
      const double cosIncident = glm::dot(ray, normal);
      if (!(cosIncident > 0.0)) continue;  // grazing the back of a wave: no light enters
      const glm::dvec3 dir = refractSunRay(ray, at.slopeX, at.slopeZ, desc.ior);
      if (!(dir.y < 0.0)) continue;
      const double w = weight * fresnelTransmittance(cosIncident, desc.ior) / flatTransmittance;
      for (size_t r = 0; r < desc.receivers.size(); ++r) {
        const double t = hitReceiver(desc.receivers[r], point, dir);
        if (!(t >= 0.0)) continue;
        const double x = point.x + dir.x * t, z = point.z + dir.z * t;
        const double fx = std::floor((x - bins.origin.x) / binSize.x);
        const double fz = std::floor((z - bins.origin.y) / binSize.y);
        if (fx < 0.0 || fz < 0.0 || fx >= bins.countX || fz >= bins.countZ) continue;
        const size_t index = static_cast<size_t>(fz) * bins.countX + static_cast<size_t>(fx);
        const double value = desc.absorption > 0.0 ? w * std::exp(-desc.absorption * t) : w;
        acc.sum[r][index] += value;
        acc.sumSquares[r][index] += value * value;
        ++acc.hits[r][index];
      }
    }
  }
};

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  const size_t mid = values.size() / 2;
  std::nth_element(values.begin(), values.begin() + static_cast<long>(mid), values.end());
  return values[mid];
}

}  // namespace

double fresnelTransmittance(double cosIncident, double ior) {
  const double ci = std::clamp(cosIncident, 0.0, 1.0);
  const double si2 = 1.0 - ci * ci;
  const double st2 = si2 / (ior * ior);
  if (st2 >= 1.0) return 0.0;
  const double ct = std::sqrt(1.0 - st2);
  const double rs = (ci - ior * ct) / (ci + ior * ct);
  const double rp = (ior * ci - ct) / (ior * ci + ct);
  const double t = 1.0 - 0.5 * (rs * rs + rp * rp);
  return std::isfinite(t) ? std::clamp(t, 0.0, 1.0) : 0.0;
}

double fresnelReflectance(double cosIncident, double ior) {
  const double ci = std::clamp(cosIncident, 0.0, 1.0);
  const double si2 = 1.0 - ci * ci;
  const double st2 = si2 / (ior * ior);
  if (st2 >= 1.0) return 1.0;  // total internal reflection (ior < 1 only)
  const double ct = std::sqrt(1.0 - st2);
  const double rs = (ci - ior * ct) / (ci + ior * ct);
  const double rp = (ior * ci - ct) / (ior * ci + ct);
  const double r = 0.5 * (rs * rs + rp * rp);
  return std::isfinite(r) ? std::clamp(r, 0.0, 1.0) : 1.0;
}

glm::dvec3 refractSunRay(const glm::dvec3& towardSun, double slopeX, double slopeZ, double ior) {
  const glm::dvec3 normal = glm::normalize(glm::dvec3(-slopeX, 1.0, -slopeZ));
  return glm::refract(-glm::normalize(towardSun), normal, 1.0 / ior);
}

glm::dvec3 sunRayHitsSurface(const Surface& surface, const glm::dvec3& sun, double u, double v,
                             SurfaceSample& at) {
  const double maxHeight = surface.maxHeight();
  const double horizontal = std::hypot(sun.x, sun.z);
  if (horizontal * maxHeight < 1e-12 * sun.y) {
    at = surface.sample(u, v);
    return glm::dvec3(u, at.height, v);
  }
  // Ray r(t) = (u, 0, v) + sun * t, from above the crests (t > 0) down below the troughs.
  const double top = (maxHeight + 1e-9) / sun.y;
  auto above = [&](double t) {
    return sun.y * t - surface.sample(u + sun.x * t, v + sun.z * t).height;
  };
  const double step = 0.25 * surface.featureSize() / horizontal;
  const double t = firstCrossing(above, top, -top, step, -top);  // f(-top) < 0 always
  const glm::dvec3 point(u + sun.x * t, sun.y * t, v + sun.z * t);
  at = surface.sample(point.x, point.z);
  return point;
}

double maxSlopeDrift(const glm::dvec3& sun, double ior, double maxSlope) {
  const glm::dvec2 flatDrift = lateral(refractSunRay(sun, 0.0, 0.0, ior));
  double slopeDrift = 0.0;
  for (int r = 1; r <= 8 && maxSlope > 0.0; ++r) {
    for (int a = 0; a < 64; ++a) {
      const double angle = 6.283185307179586 * a / 64.0, radius = maxSlope * r / 8.0;
      const glm::dvec3 t =
          refractSunRay(sun, radius * std::cos(angle), radius * std::sin(angle), ior);
      const double drift = t.y < -1e-3 ? glm::length(lateral(t) - flatDrift) : 1e3;
      slopeDrift = std::max(slopeDrift, std::min(drift, 1e3));
    }
  }
  return slopeDrift;
}

ReferenceResult traceSeabedCaustics(const Surface& surface, const ReferenceDesc& desc) {
  ReferenceResult result;
  const glm::dvec3 sun = glm::normalize(desc.towardSun);
  if (!(sun.y > 0.0) || desc.receivers.empty() || desc.bins.countX <= 0 || desc.bins.countZ <= 0 ||
      !(desc.bins.binSize > 0.0))
    return result;
  const LaunchWindow window = launchWindow(surface, desc, sun);
  result.launchMargin = window.margin;
  const Tracer tracer{surface,
                      desc,
                      sun,
                      fresnelTransmittance(sun.y, desc.ior),
                      surface.maxHeight(),
                      SunDisc(sun, desc.sunAngularRadius)};
  const glm::dvec2 cell = desc.bins.size() / static_cast<double>(std::max(desc.raysPerBinSide, 1));
  const int columns = static_cast<int>(std::ceil((window.max.x - window.min.x) / cell.x));
  const int rows = static_cast<int>(std::ceil((window.max.y - window.min.y) / cell.y));
  const size_t binCount = static_cast<size_t>(desc.bins.countX) * desc.bins.countZ;
  const size_t receiverCount = desc.receivers.size();
  const int threadCount = std::max(1, desc.threads);
  const double binArea = desc.bins.size().x * desc.bins.size().y;

  Accumulator total;
  total.reset(receiverCount, binCount);
  std::vector<Accumulator> partial(static_cast<size_t>(threadCount));
  result.receivers.assign(receiverCount, ReceiverResult{});
  const auto start = std::chrono::steady_clock::now();
  auto lastReport = start;
  for (int batch = 0;; ++batch) {
    std::vector<std::thread> threads;
    for (int id = 0; id < threadCount; ++id) {
      partial[static_cast<size_t>(id)].reset(receiverCount, binCount);
      threads.emplace_back([&, id] {
        for (int row = id; row < rows; row += threadCount)
          tracer.traceRow(batch, row, window, cell, columns, partial[static_cast<size_t>(id)]);
      });
    }
    for (std::thread& t : threads) t.join();
    for (const Accumulator& p : partial) total.add(p);  // fixed order: deterministic sums
    result.batches = batch + 1;
    result.rays += static_cast<std::uint64_t>(rows) * static_cast<std::uint64_t>(columns);

    bool allConverged = true;
    double worstMedian = 0.0;
    for (size_t r = 0; r < receiverCount; ++r) {
      ReceiverResult& out = result.receivers[r];
      out.irradiance.resize(binCount);
      out.relativeError.resize(binCount);
      out.hits = total.hits[r];
      for (size_t i = 0; i < binCount; ++i) {
        const double s = total.sum[r][i];
        out.irradiance[i] = s / (binArea * result.batches);
        out.relativeError[i] = s > 0.0 ? std::sqrt(total.sumSquares[r][i]) / s : 1.0;
      }
      out.medianRelativeError = median(out.relativeError);
      worstMedian = std::max(worstMedian, out.medianRelativeError);
      allConverged = allConverged && out.medianRelativeError < desc.targetRelativeError;
    }
    const bool capped = result.rays >= desc.maxRays;
    const auto now = std::chrono::steady_clock::now();
    const bool done = allConverged || capped;
    if (desc.progress && (done || now - lastReport > std::chrono::seconds(2))) {
      lastReport = now;
      std::fprintf(
          stderr,
          "%s: batch %d, %.3g rays, median relative error %.3f %% (target %.3g %%)%s, %.1f s\n",
          desc.label, result.batches, static_cast<double>(result.rays), 100.0 * worstMedian,
          100.0 * desc.targetRelativeError,
          done ? (allConverged ? ", converged" : ", RAY CAP REACHED") : "",
          std::chrono::duration<double>(now - start).count());
    }
    if (done) {
      result.converged = allConverged;
      break;
    }
  }
  return result;
}

}  // namespace ocean::reference
