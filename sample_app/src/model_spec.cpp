#include "model_spec.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

namespace ocean {

namespace {

// A whole-string finite number.
bool parseNumber(const std::string& text, double& value) {
  if (text.empty()) return false;
  char* end = nullptr;
  errno = 0;
  value = std::strtod(text.c_str(), &end);
  return errno == 0 && end == text.c_str() + text.size() && std::isfinite(value);
}

// Models larger than this (after fitting) would not fit the sample's scene, smaller ones are
// specks below a pixel.
constexpr double kMinFit = 0.01, kMaxFit = 100.0;
constexpr double kMaxPosition = 1000.0;

}  // namespace

bool parseModelSpec(const std::string& text, ModelSpec& out, std::string& error) {
  out = ModelSpec{};
  std::string rest = text;
  const std::string fitKey = ":fit=";
  if (const auto at = rest.rfind(fitKey); at != std::string::npos) {
    const std::string value = rest.substr(at + fitKey.size());
    double metres = 0.0;
    if (value == "none") {
      out.fitMetres.reset();
    } else if (parseNumber(value, metres) && metres >= kMinFit && metres <= kMaxFit) {
      out.fitMetres = metres;
    } else {
      error = "--model '" + text +
              "': fit must be a size in metres in [0.01, 100] or 'none', got '" + value + "'";
      return false;
    }
    rest.resize(at);
  }
  if (const auto at = rest.rfind('@'); at != std::string::npos) {
    const std::string value = rest.substr(at + 1);
    std::vector<std::string> parts(1);
    for (char c : value) {
      if (c == ',') {
        parts.emplace_back();
      } else {
        parts.back() += c;
      }
    }
    glm::dvec3 p(0.0);
    int parsed = 0;
    while (parts.size() == 3 && parsed < 3 && parseNumber(parts[std::size_t(parsed)], p[parsed]) &&
           std::abs(p[parsed]) <= kMaxPosition) {
      ++parsed;
    }
    if (parsed != 3) {
      error = "--model '" + text +
              "': position must be @x,y,z in metres (|value| <= 1000), got '@" + value + "'";
      return false;
    }
    out.position = p;
    rest.resize(at);
  }
  if (rest.empty()) {
    error = "--model '" + text + "': no file name";
    return false;
  }
  out.path = rest;
  return true;
}

bool placementTransform(const ModelSpec& spec, const glm::dvec3& lo, const glm::dvec3& hi,
                        const glm::dvec2& defaultXZ, double (*sandHeight)(double x, double z),
                        glm::dmat4& out, std::string& error) {
  const glm::dvec3 size = hi - lo;
  const auto finite = [](const glm::dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
  };
  // An empty model's box is +inf..-inf: not finite, so refused here too.
  if (!finite(lo) || !finite(hi) || size.x < 0.0 || size.y < 0.0 || size.z < 0.0) {
    error = "the model has no finite bounding box";
    return false;
  }
  const double largest = std::max({size.x, size.y, size.z});
  double scale = 1.0;
  if (spec.fitMetres) {
    if (!(largest > 0.0)) {
      error = "the model's bounding box has no extent to fit";
      return false;
    }
    scale = *spec.fitMetres / largest;
  }
  const glm::dvec2 xz = spec.position ? glm::dvec2(spec.position->x, spec.position->z) : defaultXZ;
  const double above = spec.position ? spec.position->y : 0.0;
  const glm::dvec3 centre = 0.5 * (lo + hi);
  // Bottom centre of the box to the origin, scale, then onto the sand.
  out = glm::translate(glm::dmat4(1.0), glm::dvec3(xz.x, sandHeight(xz.x, xz.y) + above, xz.y)) *
        glm::scale(glm::dmat4(1.0), glm::dvec3(scale)) *
        glm::translate(glm::dmat4(1.0), -glm::dvec3(centre.x, lo.y, centre.z));
  return true;
}

}  // namespace ocean
