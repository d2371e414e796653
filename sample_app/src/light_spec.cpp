#include "light_spec.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <vector>

namespace ocean {
namespace {

std::vector<std::string_view> split(std::string_view text, char separator) {
  std::vector<std::string_view> parts;
  size_t start = 0;
  while (true) {
    const size_t at = text.find(separator, start);
    parts.push_back(
        text.substr(start, at == std::string_view::npos ? std::string_view::npos : at - start));
    if (at == std::string_view::npos) return parts;
    start = at + 1;
  }
}

// A finite number strtod reads whole, within [lo, hi].
bool number(std::string_view text, double lo, double hi, double& value) {
  const std::string copy(text);
  char* end = nullptr;
  errno = 0;
  value = std::strtod(copy.c_str(), &end);
  return !copy.empty() && end == copy.c_str() + copy.size() && errno != ERANGE && value >= lo &&
         value <= hi;
}

// `count` comma-separated numbers in [lo, hi].
bool numbers(std::string_view text, int count, double lo, double hi, glm::dvec3& value) {
  const std::vector<std::string_view> parts = split(text, ',');
  if (int(parts.size()) != count) return false;
  for (int i = 0; i < count; ++i)
    if (!number(parts[size_t(i)], lo, hi, value[i])) return false;
  return true;
}

constexpr double kMaxCoordinate = 1e7;  // as --camera-position
constexpr double kMaxIntensity = 1e9;   // postfx::kLightIntensityRange
constexpr double kMaxRange = 1e6;       // postfx::kLightRangeRange

}  // namespace

bool parseLightSpec(std::string_view text, SceneLight& out, std::string& error) {
  const std::string prefix = "--light '" + std::string(text) + "': ";
  const std::vector<std::string_view> f = split(text, ':');
  SceneLight light;
  if (f[0] == "point") {
    light.type = SceneLight::Type::Point;
    if (f.size() < 3 || f.size() > 4) {
      error = prefix + "expected point:X,Y,Z:I[:RANGE]";
      return false;
    }
  } else if (f[0] == "spot") {
    light.type = SceneLight::Type::Spot;
    if (f.size() < 5 || f.size() > 7) {
      error = prefix + "expected spot:X,Y,Z:DX,DY,DZ:I:CONE[:SOFTNESS[:RANGE]]";
      return false;
    }
  } else {
    error = prefix + "the type must be point or spot";
    return false;
  }
  if (!numbers(f[1], 3, -kMaxCoordinate, kMaxCoordinate, light.position)) {
    error = prefix + "the position must be X,Y,Z in metres, each within +-1e7";
    return false;
  }
  const bool spot = light.type == SceneLight::Type::Spot;
  size_t next = 2;
  if (spot) {
    glm::dvec3 axis;
    if (!numbers(f[next], 3, -1e6, 1e6, axis) || !(glm::length(axis) > 1e-9)) {
      error = prefix + "the direction must be DX,DY,DZ, not all 0, each within +-1e6";
      return false;
    }
    light.direction = glm::normalize(axis);
    ++next;
  }
  glm::dvec3 intensity;
  if (numbers(f[next], 1, 0.0, kMaxIntensity, intensity)) {
    light.intensity = glm::vec3(float(intensity.x));
  } else if (numbers(f[next], 3, 0.0, kMaxIntensity, intensity)) {
    light.intensity = glm::vec3(intensity);
  } else {
    error = prefix + "the intensity must be I or R,G,B, each in [0, 1e9]";
    return false;
  }
  ++next;
  double value = 0.0;
  if (spot) {
    if (!number(f[next], 0.0, 180.0, value) || value <= 0.0 || value >= 180.0) {
      error = prefix + "the cone angle must be in (0, 180) degrees";
      return false;
    }
    light.coneAngleDegrees = float(value);
    ++next;
    if (next < f.size()) {
      if (!number(f[next], 0.0, 1.0, value)) {
        error = prefix + "the cone softness must be in [0, 1]";
        return false;
      }
      light.coneSoftness = float(value);
      ++next;
    }
  }
  if (next < f.size()) {
    if (!number(f[next], 0.0, kMaxRange, value)) {
      error = prefix + "the range must be in [0, 1e6] metres";
      return false;
    }
    light.range = value;
  }
  out = light;
  return true;
}

}  // namespace ocean
