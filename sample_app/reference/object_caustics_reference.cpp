#include "object_caustics_reference.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <mutex>
#include <optional>
#include <random>
#include <thread>

#include "object_caustics_local_light.h"
#include "object_caustics_optics.h"

namespace ocean::reference {
namespace {

struct Landing {
  glm::dvec3 point;
  glm::dvec3 flux;  // fraction of the ray's flux that arrives
};

// Returns nothing when the ray misses the caster; a landing with zero flux when it hits but its
// light never reaches the plane.
using TraceFn = std::function<std::optional<Landing>(const glm::dvec3& origin,
                                                     const glm::dvec3& dir, std::mt19937_64& rng)>;

// A rough surface's outgoing direction: `d` deflected by independent Gaussians of standard
// deviation `alpha` (radians) along two axes across it (the plugin's splat widening in
// CasterMaterial::roughness is this cone's footprint).
glm::dvec3 roughen(const glm::dvec3& d, double alpha, std::mt19937_64& rng) {
  if (!(alpha > 0.0)) return d;
  const glm::dvec3 ref = std::abs(d.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
  const glm::dvec3 a = glm::normalize(glm::cross(ref, d)), b = glm::cross(d, a);
  std::normal_distribution<double> gauss(0.0, alpha);
  return glm::normalize(d + a * std::tan(gauss(rng)) + b * std::tan(gauss(rng)));
}

std::optional<glm::dvec3> landOnPlane(const glm::dvec3& p, const glm::dvec3& d, double planeY) {
  if (!(d.y < -1e-12)) return std::nullopt;
  const double t = (planeY - p.y) / d.y;
  if (t < 0.0) return std::nullopt;
  return p + d * t;
}

CausticReference trace(const TraceFn& fn, const glm::dvec3& centre, double halfSide,
                       const glm::dvec3& towardSun, const postfx::ObjectCausticMap& map, int n,
                       const char* name, unsigned seed = 0) {
  const glm::dvec3 d = -glm::normalize(towardSun);
  const glm::dvec3 ref = std::abs(d.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
  const glm::dvec3 right = glm::normalize(glm::cross(ref, d)), up = glm::cross(d, right);
  const double cell = 2.0 * halfSide / n;
  const glm::dvec3 start = centre - d * (10.0 * halfSide + 10.0);
  const int size = map.size;
  const double u2 = glm::dot(map.axisU, map.axisU), v2 = glm::dot(map.axisV, map.axisV);
  const double texelArea = std::sqrt(u2 * v2) / (double(size) * size);
  const ReceiverBins bins{map.origin, map.axisU, map.axisV, size};  // the map's texels
  CausticReference out;
  out.size = size;
  out.irradiance.assign(static_cast<size_t>(size) * size, glm::dvec3(0.0));
  std::mutex merge;
  const int threads = 2;
  auto work = [&](int t) {
    CausticReference local;
    local.irradiance.assign(static_cast<size_t>(size) * size, glm::dvec3(0.0));
    for (int j = t; j < n; j += threads) {
      if (t == 0 && (j % (n / 4 + 1)) == 0)
        std::fprintf(stderr, "[reference %s] %d%%\n", name, 100 * j / n);
      std::mt19937_64 rng(0x5eedULL + static_cast<unsigned long long>(j) +
                          (static_cast<unsigned long long>(seed) << 32));
      std::uniform_real_distribution<double> jitter(0.0, 1.0);
      for (int i = 0; i < n; ++i) {
        const double a = -halfSide + (i + jitter(rng)) * cell;
        const double b = -halfSide + (j + jitter(rng)) * cell;
        const std::optional<Landing> l = fn(start + right * a + up * b, d, rng);
        if (!l) continue;
        local.interceptedArea += cell * cell;
        const glm::dvec3 flux = l->flux * (cell * cell);
        if (flux == glm::dvec3(0.0)) continue;
        const std::ptrdiff_t bin = binIndex(bins, l->point);
        if (bin >= 0) {
          local.irradiance[static_cast<size_t>(bin)] += flux / texelArea;
          local.fluxInMap += flux;
        } else {
          local.fluxOutside += flux;
        }
      }
    }
    std::lock_guard<std::mutex> lock(merge);
    for (size_t k = 0; k < out.irradiance.size(); ++k) out.irradiance[k] += local.irradiance[k];
    out.fluxInMap += local.fluxInMap;
    out.fluxOutside += local.fluxOutside;
    out.interceptedArea += local.interceptedArea;
  };
  std::vector<std::thread> pool;
  for (int t = 0; t < threads; ++t) pool.emplace_back(work, t);
  for (std::thread& th : pool) th.join();
  std::fprintf(stderr, "[reference %s] 100%%\n", name);
  return out;
}

}  // namespace

namespace {

CausticReference traceOneIor(const SphereCaster& s, const glm::dvec3& towardSun, double planeY,
                             const postfx::ObjectCausticMap& map, int raysPerSide, unsigned seed) {
  const double alpha = s.roughness * s.roughness;
  const glm::dvec3 weight = s.transmission * s.tint;
  const TraceFn fn = [&s, planeY, alpha, weight](const glm::dvec3& o, const glm::dvec3& d,
                                                 std::mt19937_64& rng) -> std::optional<Landing> {
    const std::optional<SphereCrossing> x = crossSphere(s.centre, s.radius, s.ior, o, d);
    if (!x) return std::nullopt;
    Landing none{x->entry, glm::dvec3(0.0)};
    const double t1 = x->entryTransmittance;
    if (s.thinWalled) {
      const std::optional<glm::dvec3> hit = landOnPlane(x->entry, roughen(d, alpha, rng), planeY);
      if (!hit) return none;
      return Landing{*hit, t1 * t1 * weight};
    }
    if (!x->refracted) return none;
    const double t2 = x->exitTransmittance, chord = x->chord;
    const std::optional<glm::dvec3> hit = landOnPlane(x->exit, roughen(x->out, alpha, rng), planeY);
    if (!hit) return none;
    return Landing{*hit, t1 * t2 * weight * glm::exp(-s.absorption * chord)};
  };
  return trace(fn, s.centre, s.radius * 1.01, towardSun, map, raysPerSide, "sphere", seed);
}

}  // namespace

CausticReference traceSphereReference(const SphereCaster& s, const glm::dvec3& towardSun,
                                      double planeY, const postfx::ObjectCausticMap& map,
                                      int raysPerSide, unsigned seed) {
  if (!(s.dispersion > 0.0)) return traceOneIor(s, towardSun, planeY, map, raysPerSide, seed);
  // One trace per channel with that channel's IOR, keeping only its own colour.
  CausticReference sum;
  const double halfSpread = (s.ior - 1.0) * 0.025 * s.dispersion;
  for (int c = 0; c < 3; ++c) {
    SphereCaster channel = s;
    channel.dispersion = 0.0;
    channel.ior = s.ior + (c - 1) * halfSpread;
    glm::dvec3 mask(0.0);
    mask[c] = 1.0;
    channel.tint = s.tint * mask;
    const CausticReference one = traceOneIor(channel, towardSun, planeY, map, raysPerSide, seed);
    if (c == 0) {
      sum = one;
      continue;
    }
    for (size_t k = 0; k < sum.irradiance.size(); ++k) sum.irradiance[k] += one.irradiance[k];
    sum.fluxInMap += one.fluxInMap;
    sum.fluxOutside += one.fluxOutside;
  }
  return sum;
}

std::optional<RingReflection> reflectOffRing(const RingCaster& r, const glm::dvec3& o,
                                             const glm::dvec3& d) {
  const double top = r.base.y + r.height, bottom = r.base.y;
  auto radial = [&r](const glm::dvec3& p) { return glm::dvec2(p.x - r.base.x, p.z - r.base.z); };
  // Roots of |radial(o + t d)| = radius.
  auto cylinder = [&](double radius, double& t0, double& t1) {
    const glm::dvec2 q = radial(o), e(d.x, d.z);
    const double a = glm::dot(e, e), b = glm::dot(q, e), c = glm::dot(q, q) - radius * radius;
    const double disc = b * b - a * c;
    if (a < 1e-18 || disc <= 0.0) return false;
    t0 = (-b - std::sqrt(disc)) / a;
    t1 = (-b + std::sqrt(disc)) / a;
    return true;
  };
  const double tTop = (top - o.y) / d.y;
  const double rTop = glm::length(radial(o + d * tTop));
  glm::dvec3 p, n;
  if (rTop <= r.inner) {  // through the opening: the far inner wall, or the floor inside
    double t0, t1;
    if (!cylinder(r.inner, t0, t1)) return std::nullopt;
    p = o + d * t1;
    if (p.y < bottom) return std::nullopt;
    const glm::dvec2 q = radial(p) / r.inner;
    n = glm::dvec3(-q.x, 0.0, -q.y);
  } else if (rTop <= r.outer) {  // top annulus
    p = o + d * tTop;
    n = glm::dvec3(0.0, 1.0, 0.0);
  } else {  // beside the top: the outer wall, if the ray meets it below the top
    double t0, t1;
    if (!cylinder(r.outer, t0, t1) || t0 < tTop) return std::nullopt;
    p = o + d * t0;
    if (p.y < bottom) return std::nullopt;
    const glm::dvec2 q = radial(p) / r.outer;
    n = glm::dvec3(q.x, 0.0, q.y);
  }
  const double cosI = -glm::dot(d, n);
  const double m = 1.0 - std::clamp(cosI, 0.0, 1.0);
  return RingReflection{p, d + 2.0 * cosI * n,
                        r.f0 + (glm::dvec3(1.0) - r.f0) * (m * m * m * m * m)};
}

CausticReference traceRingReference(const RingCaster& r, const glm::dvec3& towardSun, double planeY,
                                    const postfx::ObjectCausticMap& map, int raysPerSide) {
  const TraceFn fn = [&r, planeY](const glm::dvec3& o, const glm::dvec3& d,
                                  std::mt19937_64&) -> std::optional<Landing> {
    const std::optional<RingReflection> hit = reflectOffRing(r, o, d);
    if (!hit) return std::nullopt;
    const std::optional<glm::dvec3> landed = landOnPlane(hit->point, hit->direction, planeY);
    if (!landed) return Landing{hit->point, glm::dvec3(0.0)};
    return Landing{*landed, hit->reflectance};
  };
  const glm::dvec3 centre = r.base + glm::dvec3(0.0, 0.5 * r.height, 0.0);
  return trace(fn, centre, std::hypot(r.outer, 0.5 * r.height) * 1.01, towardSun, map, raysPerSide,
               "ring");
}

SphereOverPlane glassSphereOverPlane() {
  const double pi = 3.14159265358979323846;
  const double zenith = 25.0 * pi / 180.0, azimuth = 40.0 * pi / 180.0;  // azimuth from +x to +z
  SphereOverPlane s;
  s.sphere.centre = {0.3, 1.4, -0.2};
  s.sphere.radius = 1.0;
  s.sphere.ior = 1.5;
  s.sphere.absorption = {0.02, 0.1, 0.3};
  s.towardSun = {std::sin(zenith) * std::cos(azimuth), std::cos(zenith),
                 std::sin(zenith) * std::sin(azimuth)};
  s.planeY = 0.0;
  return s;
}

std::vector<glm::dvec3> gaussianBlur(const std::vector<glm::dvec3>& map, int size, double sigma) {
  const int radius = static_cast<int>(std::ceil(3.0 * sigma));
  std::vector<double> kernel(2 * radius + 1);
  double sum = 0.0;
  for (int k = -radius; k <= radius; ++k)
    sum += kernel[k + radius] = std::exp(-k * k / (2 * sigma * sigma));
  for (double& k : kernel) k /= sum;
  std::vector<glm::dvec3> tmp(map.size(), glm::dvec3(0.0)), out(map.size(), glm::dvec3(0.0));
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x)
      for (int k = -radius; k <= radius; ++k) {
        const int xx = x + k;
        if (xx >= 0 && xx < size) tmp[y * size + x] += map[y * size + xx] * kernel[k + radius];
      }
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x)
      for (int k = -radius; k <= radius; ++k) {
        const int yy = y + k;
        if (yy >= 0 && yy < size) out[y * size + x] += tmp[yy * size + x] * kernel[k + radius];
      }
  return out;
}

}  // namespace ocean::reference
