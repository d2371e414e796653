#include "object_caustics_local_light.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <mutex>
#include <optional>
#include <random>
#include <thread>

#include "object_caustics_optics.h"

namespace ocean::reference {
namespace {

constexpr double kPi = 3.14159265358979323846;

// What is left of a ray's flux after the caster (cone and leg-1 absorption included), and where
// it goes from there.
struct Departure {
  glm::dvec3 point;
  glm::dvec3 direction;  // unit
  glm::dvec3 throughput;
};
// Nothing: the ray's light never leaves toward the receiver (missed the caster, or reflected).
using DepartFn = std::function<std::optional<Departure>(const glm::dvec3& dir)>;

double smoothstep(double edge0, double edge1, double x) {
  const double t = std::clamp((x - edge0) / (edge1 - edge0), 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

// Any unit vector perpendicular to unit `axis`.
glm::dvec3 perpendicular(const glm::dvec3& axis) {
  const glm::dvec3 ref = std::abs(axis.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
  return glm::normalize(glm::cross(ref, axis));
}

// raysPerSide^2 rays from `light` over the cap of directions within acos(cosMax) of unit `axis`
// (stratified in (1 - cos theta, phi): equal solid angle per stratum), each carrying the
// light's intensity times its solid angle, through `depart` and on to the plane of `bins`.
LocalCausticReference traceCap(const LocalLightSource& light, const glm::dvec3& axis, double cosMax,
                               const ReceiverBins& bins, const glm::dvec3& absorption, int n,
                               unsigned seed, const DepartFn& depart) {
  const glm::dvec3 a = perpendicular(axis), b = glm::cross(axis, a);
  const double solidAngle = 2.0 * kPi * (1.0 - cosMax);
  const double rayAngle = solidAngle / (double(n) * n);
  const int size = bins.size;
  const glm::dvec3 normal = glm::normalize(glm::cross(bins.axisU, bins.axisV));
  const double area = binArea(bins);
  LocalCausticReference out;
  out.size = size;
  out.solidAngle = solidAngle;
  out.irradiance.assign(size_t(size) * size, glm::dvec3(0.0));
  out.fluxEmitted = light.intensity * solidAngle;
  std::mutex merge;
  const int threads = 2;
  auto work = [&](int t) {
    LocalCausticReference local;
    local.irradiance.assign(size_t(size) * size, glm::dvec3(0.0));
    for (int j = t; j < n; j += threads) {
      std::mt19937_64 rng(0x11947ULL + static_cast<unsigned long long>(j) +
                          (static_cast<unsigned long long>(seed) << 32));
      std::uniform_real_distribution<double> jitter(0.0, 1.0);
      for (int i = 0; i < n; ++i) {
        const double cosTheta = 1.0 - (i + jitter(rng)) / n * (1.0 - cosMax);
        const double phi = 2.0 * kPi * (j + jitter(rng)) / n;
        const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
        const glm::dvec3 dir = axis * cosTheta + (a * std::cos(phi) + b * std::sin(phi)) * sinTheta;
        const double cone = coneFactor(light, dir);
        if (cone == 0.0) continue;
        const std::optional<Departure> d = depart(dir);
        if (!d) continue;
        const glm::dvec3 flux = light.intensity * (cone * rayAngle) * d->throughput;
        local.fluxLeaving += flux;
        const double facing = glm::dot(d->direction, normal);
        if (std::abs(facing) < 1e-15) continue;
        const double along = glm::dot(bins.origin - d->point, normal) / facing;
        if (!(along > 0.0)) continue;
        const glm::dvec3 landed = flux * glm::exp(-absorption * along);
        const std::ptrdiff_t bin = binIndex(bins, d->point + d->direction * along);
        if (bin >= 0) {
          local.irradiance[size_t(bin)] += landed / area;
          local.fluxInBins += landed;
        } else {
          local.fluxOutside += landed;
        }
      }
    }
    std::lock_guard<std::mutex> lock(merge);
    for (size_t k = 0; k < out.irradiance.size(); ++k) out.irradiance[k] += local.irradiance[k];
    out.fluxInBins += local.fluxInBins;
    out.fluxOutside += local.fluxOutside;
    out.fluxLeaving += local.fluxLeaving;
  };
  std::vector<std::thread> pool;
  for (int t = 0; t < threads; ++t) pool.emplace_back(work, t);
  for (std::thread& th : pool) th.join();
  return out;
}

}  // namespace

double coneFactor(const LocalLightSource& light, const glm::dvec3& dir) {
  if (!light.spot) return 1.0;
  const double half = 0.5 * light.coneAngleDegrees * kPi / 180.0;
  const double angle =
      std::acos(std::clamp(glm::dot(glm::normalize(light.direction), dir), -1.0, 1.0));
  if (angle >= half) return 0.0;
  const double inner = half * (1.0 - std::clamp(light.coneSoftness, 0.0, 1.0));
  if (angle <= inner) return 1.0;
  return 1.0 - smoothstep(inner, half, angle);
}

ReceiverBins floorBins(const glm::dvec3& centre, double planeY, double side, int size) {
  ReceiverBins bins;
  bins.origin = {centre.x - 0.5 * side, planeY, centre.z - 0.5 * side};
  bins.axisU = {side, 0.0, 0.0};
  bins.axisV = {0.0, 0.0, side};
  bins.size = size;
  return bins;
}

ReceiverBins facingBins(const glm::dvec3& light, const glm::dvec3& axis, double distance,
                        double side, int size) {
  const glm::dvec3 u = perpendicular(axis), v = glm::cross(axis, u);
  ReceiverBins bins;
  bins.axisU = u * side;
  bins.axisV = v * side;
  bins.origin = light + axis * distance - 0.5 * (bins.axisU + bins.axisV);
  bins.size = size;
  return bins;
}

glm::dvec3 binPoint(const ReceiverBins& bins, const glm::dvec2& bin) {
  return bins.origin + (bin.x / bins.size) * bins.axisU + (bin.y / bins.size) * bins.axisV;
}

double binArea(const ReceiverBins& bins) {
  return glm::length(glm::cross(bins.axisU, bins.axisV)) / (double(bins.size) * bins.size);
}

std::ptrdiff_t binIndex(const ReceiverBins& bins, const glm::dvec3& point) {
  const glm::dvec3 rel = point - bins.origin;
  const double size = bins.size;
  const double tu = glm::dot(rel, bins.axisU) / glm::dot(bins.axisU, bins.axisU) * size;
  const double tv = glm::dot(rel, bins.axisV) / glm::dot(bins.axisV, bins.axisV) * size;
  if (!(tu >= 0.0 && tv >= 0.0 && tu < size && tv < size)) return -1;
  return std::ptrdiff_t(tv) * bins.size + std::ptrdiff_t(tu);
}

SphereRay traceThroughSphere(const SphereCaster& s, const glm::dvec3& origin,
                             const glm::dvec3& dir) {
  SphereRay ray;
  const glm::dvec3 weight = s.transmission * s.tint;
  const glm::dvec3 oc = origin - s.centre;
  const double b = glm::dot(oc, dir), c = glm::dot(oc, oc) - s.radius * s.radius;
  const double disc = b * b - c;
  if (c > 0.0) {  // outside: in through the near side, out through the far side
    if (disc <= 0.0 || -b - std::sqrt(disc) < 0.0) return ray;
    ray.hit = true;
    ray.entry = origin + dir * (-b - std::sqrt(disc));
    const glm::dvec3 n1 = (ray.entry - s.centre) / s.radius;
    const double t1 = 1.0 - fresnel(-glm::dot(dir, n1), s.ior);
    if (s.thinWalled) {
      ray.leaves = true;
      ray.exit = ray.entry;
      ray.direction = dir;
      ray.transmittance = t1 * t1 * weight;
      return ray;
    }
    const std::optional<glm::dvec3> in = refractRay(dir, n1, 1.0 / s.ior);
    if (!in) return ray;
    const glm::dvec3 inside = glm::normalize(*in);
    const double chord = -2.0 * glm::dot(ray.entry - s.centre, inside);
    ray.exit = ray.entry + inside * chord;
    const glm::dvec3 n2 = (ray.exit - s.centre) / s.radius;
    const std::optional<glm::dvec3> out = refractRay(inside, -n2, s.ior);
    if (!out) return ray;  // total internal reflection (never for a sphere)
    const double t2 = 1.0 - fresnel(glm::dot(inside, n2), 1.0 / s.ior);
    ray.leaves = true;
    ray.direction = glm::normalize(*out);
    ray.transmittance = t1 * t2 * weight * glm::exp(-s.absorption * chord);
    return ray;
  }
  // Inside (or on) the sphere: only the way out.
  ray.hit = true;
  ray.entry = origin;
  const double along = -b + std::sqrt(std::max(0.0, disc));
  ray.exit = origin + dir * along;
  const glm::dvec3 n2 = (ray.exit - s.centre) / s.radius;
  if (s.thinWalled) {
    ray.leaves = true;
    ray.direction = dir;
    ray.transmittance = (1.0 - fresnel(glm::dot(dir, n2), s.ior)) * weight;
    return ray;
  }
  const std::optional<glm::dvec3> out = refractRay(dir, -n2, s.ior);
  if (!out) return ray;
  ray.leaves = true;
  ray.direction = glm::normalize(*out);
  ray.transmittance =
      (1.0 - fresnel(glm::dot(dir, n2), 1.0 / s.ior)) * weight * glm::exp(-s.absorption * along);
  return ray;
}

LocalCausticReference traceSphereFromLight(const SphereCaster& sphere,
                                           const LocalLightSource& light, const ReceiverBins& bins,
                                           const glm::dvec3& absorption, int raysPerSide,
                                           unsigned seed) {
  const glm::dvec3 toCentre = sphere.centre - light.position;
  const double distance = glm::length(toCentre);
  // The cap the sphere subtends; every direction when the light is inside it.
  const bool outside = distance > sphere.radius;
  const glm::dvec3 axis = outside ? toCentre / distance : glm::dvec3(0.0, -1.0, 0.0);
  const double ratio = sphere.radius / distance;
  const double cosMax = outside ? std::sqrt(1.0 - ratio * ratio) : -1.0;
  const DepartFn depart = [&](const glm::dvec3& dir) -> std::optional<Departure> {
    const SphereRay ray = traceThroughSphere(sphere, light.position, dir);
    if (!ray.leaves) return std::nullopt;
    const double leg1 = glm::length(ray.entry - light.position);
    return Departure{ray.exit, ray.direction, ray.transmittance * glm::exp(-absorption * leg1)};
  };
  return traceCap(light, axis, cosMax, bins, absorption, raysPerSide, seed, depart);
}

LocalCausticReference traceRingFromLight(const RingCaster& ring, const LocalLightSource& light,
                                         const ReceiverBins& bins, const glm::dvec3& absorption,
                                         int raysPerSide, unsigned seed) {
  const glm::dvec3 centre = ring.base + glm::dvec3(0.0, 0.5 * ring.height, 0.0);
  const double radius = std::hypot(ring.outer, 0.5 * ring.height) * 1.01;
  const glm::dvec3 toCentre = centre - light.position;
  const double distance = glm::length(toCentre);
  if (!(light.position.y > ring.base.y + ring.height) || !(distance > radius)) {
    LocalCausticReference none;
    none.size = bins.size;
    none.irradiance.assign(size_t(bins.size) * bins.size, glm::dvec3(0.0));
    return none;
  }
  const double ratio = radius / distance;
  const DepartFn depart = [&](const glm::dvec3& dir) -> std::optional<Departure> {
    if (!(dir.y < 0.0)) return std::nullopt;
    const std::optional<RingReflection> hit = reflectOffRing(ring, light.position, dir);
    if (!hit) return std::nullopt;
    const double leg1 = glm::length(hit->point - light.position);
    return Departure{hit->point, hit->direction, hit->reflectance * glm::exp(-absorption * leg1)};
  };
  return traceCap(light, toCentre / distance, std::sqrt(1.0 - ratio * ratio), bins, absorption,
                  raysPerSide, seed, depart);
}

LocalCausticReference traceDirectLight(const LocalLightSource& light, const ReceiverBins& bins,
                                       const glm::dvec3& absorption, int raysPerSide,
                                       unsigned seed) {
  const glm::dvec3 centre = binPoint(bins, glm::dvec2(0.5 * bins.size));
  const glm::dvec3 axis = glm::normalize(centre - light.position);
  double cosMax = 1.0;
  for (const glm::dvec2 corner :
       {glm::dvec2(0, 0), glm::dvec2(1, 0), glm::dvec2(0, 1), glm::dvec2(1, 1)}) {
    const glm::dvec3 p = binPoint(bins, corner * double(bins.size));
    cosMax = std::min(cosMax, glm::dot(glm::normalize(p - light.position), axis));
  }
  cosMax = std::max(-1.0, cosMax - 1e-9);
  const DepartFn depart = [&light](const glm::dvec3& dir) -> std::optional<Departure> {
    return Departure{light.position, dir, glm::dvec3(1.0)};
  };
  return traceCap(light, axis, cosMax, bins, absorption, raysPerSide, seed, depart);
}

double axisCrossingFromCentre(const SphereCaster& sphere, const glm::dvec3& light, double angle) {
  const glm::dvec3 axis = glm::normalize(sphere.centre - light);
  const glm::dvec3 side = perpendicular(axis);
  const glm::dvec3 dir = axis * std::cos(angle) + side * std::sin(angle);
  const SphereRay ray = traceThroughSphere(sphere, light, dir);
  if (!ray.leaves) return -1.0;
  const double lateral = glm::dot(ray.exit - sphere.centre, side);
  const double rate = glm::dot(ray.direction, side);
  if (!(lateral * rate < 0.0)) return -1.0;  // moving away from the axis: no crossing
  const glm::dvec3 crossing = ray.exit - ray.direction * (lateral / rate);
  return glm::dot(crossing - sphere.centre, axis);
}

}  // namespace ocean::reference
