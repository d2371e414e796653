#include "object_caustics/object_caustics_light_frame.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace postfx::detail {
namespace {

constexpr double kPi = 3.14159265358979323846;

double angleBetween(const glm::dvec3& a, const glm::dvec3& b) {
  return std::acos(std::clamp(glm::dot(a, b), -1.0, 1.0));
}

// Distance from p to the axis-aligned box [lo, hi] (0 inside).
double distanceToBox(const glm::dvec3& p, const glm::dvec3& lo, const glm::dvec3& hi) {
  return glm::length(glm::max(glm::max(lo - p, p - hi), glm::dvec3(0.0)));
}

// Whether a spot's cone (unit axis, half-angle) meets the sphere (centre, radius) seen from p.
bool coneMeetsSphere(const glm::dvec3& p, const glm::dvec3& axis, double half,
                     const glm::dvec3& centre, double radius) {
  const glm::dvec3 d = centre - p;
  const double distance = glm::length(d);
  if (!(distance > radius)) return true;  // the light is inside the sphere
  return angleBetween(axis, d / distance) - std::asin(radius / distance) < half;
}

// The casters within the light's range and (spot) cone; InsideCaster when the light lies in one
// of their boxes.
LightSkip castersInReach(const FrameDesc& frame, const LocalLight& light, std::uint64_t& mask) {
  const ObjectCausticsFrame& objects = frame.objectCaustics;
  mask = 0;
  const bool spot = light.type == LocalLightType::Spot;
  const glm::dvec3 axis = spot ? glm::normalize(light.direction) : glm::dvec3(0.0);
  const double half = glm::radians(double(light.coneAngleDegrees)) * 0.5;
  for (int c = 0; c < objects.casterCount; ++c) {
    const std::uint64_t bit = std::uint64_t(1) << c;
    glm::dvec3 lo, hi;
    casterWorldBounds(objects, lo, hi, bit);
    const double distance = distanceToBox(light.position, lo, hi);
    if (!(distance <= light.range)) continue;
    if (distance == 0.0) return LightSkip::InsideCaster;
    if (spot &&
        !coneMeetsSphere(light.position, axis, half, 0.5 * (lo + hi), 0.5 * glm::length(hi - lo)))
      continue;
    mask |= bit;
  }
  return mask != 0 ? LightSkip::None : LightSkip::NoCasterInReach;
}

}  // namespace

LightSkip fitLocalLightFrame(const FrameDesc& frame, int index, ObjectLightFrame& f) {
  const ObjectCausticsFrame& objects = frame.objectCaustics;
  const ObjectCausticsSettings& s = objects.settings;
  if (index >= objects.lightCount || !s.enabled || !(s.intensity > 0.0f))
    return LightSkip::NoCasterInReach;
  const LocalLight& light = objects.lights[index];
  const glm::vec3 i = light.intensity;
  if (!(std::max({i.r, i.g, i.b}) > 0.0f) || !(light.range > 0.0))
    return LightSkip::NoCasterInReach;
  std::uint64_t mask = 0;
  const LightSkip reach = castersInReach(frame, light, mask);
  if (reach != LightSkip::None) return reach;
  if (!castersInReceiverView(objects, light.receivers, mask)) return LightSkip::NoCasterInReach;

  glm::dvec3 lo, hi;
  casterWorldBounds(objects, lo, hi, mask);
  const glm::dvec3 centre = 0.5 * (lo + hi);
  // The casters are refracted by the medium around them, and the light's rays reach them
  // through that medium only: a light on the other side of the water level would be refracted
  // at the surface first, which a local light's view (one centre of projection) cannot hold.
  f.underwater = centre.y < frame.water.level;
  if (f.underwater != localLightUnderwater(frame, light)) return LightSkip::AcrossWaterSurface;
  f.outerIor = f.underwater ? double(frame.water.ior) : 1.0;

  // The cone around the directions to every corner of the casters' boxes.
  const glm::dvec3 p = light.position;
  glm::dvec3 sum(0.0);
  for (int c = 0; c < objects.casterCount; ++c)
    if ((mask >> c) & 1u)
      for (int k = 0; k < 8; ++k)
        sum += glm::normalize(casterWorldCorner(objects.casters[c], k) - p);
  const double sumLength = glm::length(sum);
  if (!(sumLength > 1e-9)) return LightSkip::CastersAround;
  glm::dvec3 axis = sum / sumLength;
  double half = 0.0;
  for (int c = 0; c < objects.casterCount; ++c)
    if ((mask >> c) & 1u)
      for (int k = 0; k < 8; ++k)
        half = std::max(
            half, angleBetween(axis, glm::normalize(casterWorldCorner(objects.casters[c], k) - p)));
  // A spot narrower than the casters' cone: its own cone is the view (the rays outside it
  // carry no light).
  bool coneView = false;
  if (light.type == LocalLightType::Spot) {
    const double coneHalf = glm::radians(double(light.coneAngleDegrees)) * 0.5;
    if (coneHalf < half) {
      axis = glm::normalize(light.direction);
      half = coneHalf;
      coneView = true;
    }
  }
  if (!(half <= glm::radians(kMaxLightViewDegrees) * 0.5)) return LightSkip::CastersAround;

  f.light = index;
  f.position = p;
  f.direction = axis;
  lightAxes(axis, f.right, f.up);
  f.casters = mask;
  f.anchor = centre;
  // The square view's half side: the cone's, or (casters' view) the tightest square around
  // the corners' directions, which the cone's circle would leave a fifth of the grid wider
  // than. 2% room so that silhouettes are not cut by the view's edge (as the sun's).
  double tanHalf = std::tan(std::max(half, 1e-6));
  if (!coneView) {
    tanHalf = 1e-6;
    for (int c = 0; c < objects.casterCount; ++c)
      if ((mask >> c) & 1u)
        for (int k = 0; k < 8; ++k) {
          const glm::dvec3 q = casterWorldCorner(objects.casters[c], k) - p;
          tanHalf = std::max(tanHalf,
                             std::max(std::abs(glm::dot(q, f.right)), std::abs(glm::dot(q, f.up))) /
                                 glm::dot(q, axis));
        }
  }
  f.tanHalfGrid = tanHalf * 1.02;
  f.tanHalfMap = std::min(f.tanHalfGrid * double(s.footprintScale), std::tan(0.49 * kPi));
  double zNear = std::numeric_limits<double>::max(), zFar = 0.0;
  for (int c = 0; c < objects.casterCount; ++c)
    if ((mask >> c) & 1u)
      for (int k = 0; k < 8; ++k) {
        const double z = glm::dot(casterWorldCorner(objects.casters[c], k) - p, axis);
        zNear = std::min(zNear, z);
        zFar = std::max(zFar, z);
      }
  // Every corner lies within the view's cone (<= 80 degrees off the axis), so z > 0; a spot's
  // narrower cone can leave corners behind its plane: the near plane stays in front.
  const double room = 0.01 * (zFar - zNear) + 1e-4 * zFar;
  f.zFar = zFar + room;
  f.zNear = std::max(zNear - room, 1e-4 * f.zFar);
  f.halfGrid = f.halfMap = 0.0;  // the sun's, unused
  return LightSkip::None;
}

}  // namespace postfx::detail
