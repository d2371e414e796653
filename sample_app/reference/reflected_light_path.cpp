#include "reflected_light_path.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace ocean::reference {
namespace {

constexpr double kPi = 3.141592653589793;
// A reflected ray grazing the waves for longer than this many march steps is given up.
constexpr int kMaxMarchSteps = 4096;

// Horizontal drift per metre of rise of an upward ray, as if it rose at least at
// kMinMirrorElevation (downward rays: their horizontal direction at that elevation).
glm::dvec2 risingDrift(const glm::dvec3& ray) {
  const double cap = 1.0 / std::tan(kMinMirrorElevation);
  const glm::dvec2 across(ray.x, ray.z);
  const double horizontal = glm::length(across);
  if (!(horizontal > 0.0)) return glm::dvec2(0.0);
  if (ray.y > 0.0 && horizontal < cap * ray.y) return across / ray.y;
  return across * (cap / horizontal);
}

}  // namespace

glm::dvec3 flatMirrorDirection(const glm::dvec3& towardSun) {
  return glm::dvec3(towardSun.x, -towardSun.y, towardSun.z);
}

MirrorDrift mirrorDrift(const glm::dvec3& towardSun, double maxSlope) {
  std::vector<glm::dvec2> drifts = {risingDrift(-flatMirrorDirection(towardSun))};
  for (int r = 1; r <= 8 && maxSlope > 0.0; ++r) {
    for (int a = 0; a < 64; ++a) {
      const double angle = 2.0 * kPi * a / 64.0, radius = maxSlope * r / 8.0;
      const glm::dvec3 normal =
          glm::normalize(glm::dvec3(-radius * std::cos(angle), 1.0, -radius * std::sin(angle)));
      drifts.push_back(risingDrift(glm::reflect(-towardSun, normal)));
    }
  }
  glm::dvec2 lo = drifts.front(), hi = drifts.front();
  for (const glm::dvec2& d : drifts) {
    lo = glm::min(lo, d);
    hi = glm::max(hi, d);
  }
  MirrorDrift bounds{0.5 * (lo + hi), 0.0};
  for (const glm::dvec2& d : drifts)
    bounds.radius = std::max(bounds.radius, glm::length(d - bounds.centre));
  return bounds;
}

bool mayReceiveMirrorLight(const glm::dvec3& normal, const glm::dvec3& towardSun, double maxSlope,
                           double sunAngularRadius) {
  // Flat water's reflected ray makes angle theta with the normal; the waves and the sun's disc
  // turn it by at most `spread`. Some ray meets the face from the front (ray . normal < 0) when
  // theta + spread exceeds a right angle.
  const glm::dvec3 rising = -flatMirrorDirection(towardSun);
  const double theta = std::acos(std::clamp(glm::dot(rising, normal), -1.0, 1.0));
  const double spread = std::min(2.0 * std::atan(std::max(maxSlope, 0.0)) + sunAngularRadius, kPi);
  return theta + spread > 0.5 * kPi;
}

WaterCrossing nextWaterCrossing(const Surface& water, const glm::dvec3& from,
                                const glm::dvec3& dir) {
  const double top = water.maxHeight();
  const double horizontal = std::hypot(dir.x, dir.z);
  // The gap between the ray and the surface below it shrinks at most this fast per metre of
  // ray: a ray climbing faster than the steepest slope never meets the water again.
  const double closing = water.maxSlope() * horizontal - dir.y;
  if (!(closing > 0.0)) return {};
  const double minStep = 0.25 * water.featureSize() / std::max({horizontal, std::abs(dir.y), 1e-9});
  auto gap = [&](double t) {
    const glm::dvec3 p = from + dir * t;
    return p.y - water.sample(p.x, p.z).height;
  };
  double a = 0.0, ga = 0.0;  // the ray leaves the surface at t = 0
  for (int step = 0; step < kMaxMarchSteps; ++step) {
    if (dir.y > 0.0 && from.y + dir.y * a > top) return {};
    const double b = a + std::max(ga / closing, minStep);
    const double gb = gap(b);
    if (gb < 0.0) {
      // Bisection: the crossing to within a micrometre, kept on the air side.
      double lo = a, hi = b;
      for (int k = 0; k < 60 && hi - lo > 1e-6 * std::max(1.0, minStep); ++k) {
        const double mid = 0.5 * (lo + hi);
        (gap(mid) < 0.0 ? hi : lo) = mid;
      }
      return {WaterCrossing::Kind::Meets, lo};
    }
    a = b;
    ga = gb;
  }
  return {WaterCrossing::Kind::Lost, a};
}

}  // namespace ocean::reference
