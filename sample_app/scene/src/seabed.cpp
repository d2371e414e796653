#include "scene/seabed.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace ocean_scene {

namespace {

constexpr double kTwoPi = 6.28318530717958647692;

struct DuneTrain {
  double amplitude, wavelength, directionDeg, phase;
};

// Amplitudes sum to 1.95 m; with the slope term (<= 0.75 m at the mesh edge, clamped beyond)
// and ripples the surface stays inside [kSeabedMinHeight, kSeabedMaxHeight] away from the
// sandbank (whose top the dense-sample test bounds).
constexpr std::array<DuneTrain, 3> kDunes = {DuneTrain{1.0, 47.0, 20.0, 0.7},
                                             DuneTrain{0.6, 29.0, 75.0, 2.1},
                                             DuneTrain{0.35, 17.0, -35.0, 4.4}};

// Shelf slope: deeper towards +z, so a camera looking along +z sees the seabed fall away.
constexpr double kSlopePerMetre = -0.005;
constexpr double kSlopeLimit = 150.0;  // slope held constant beyond this |z|

constexpr double kRippleDirectionDeg = 100.0;
constexpr double kRippleWarpAmplitude = 0.6;  // metres of crest-line meander
constexpr glm::dvec2 kRippleWarpFrequency{0.23, 0.11};
constexpr double kRippleWarpPhase = 1.3;

// The sandbank's dunes are flattened by this share at its top: a bank is the sea's own
// levelling of the sand, and it keeps the shallow preset's depths within 2.5-4.5 m.
constexpr double kSandbankDuneDamping = 0.6;

glm::dvec2 direction(double degrees) {
  const double a = degrees * kTwoPi / 360.0;
  return {std::cos(a), std::sin(a)};
}

// Ripple strength by distance from the origin, and its derivative d/dr.
double rippleFade(double r, double& dFade) {
  const double span = kRippleFadeRadius - kRippleFieldRadius;
  const double t = std::clamp((r - kRippleFieldRadius) / span, 0.0, 1.0);
  dFade = (t > 0.0 && t < 1.0) ? -6.0 * t * (1.0 - t) / span : 0.0;
  return 1.0 - t * t * (3.0 - 2.0 * t);
}

// The sandbank's share at p: 1 on its top, 0 beyond its foot (smoothstep in between), and
// the gradient of that share.
double sandbankShare(const glm::dvec2& p, glm::dvec2& gradient) {
  const glm::dvec2 d = p - kSandbankXZ;
  const double r = glm::length(d);
  const double span = kSandbankFootRadius - kSandbankTopRadius;
  const double t = std::clamp((r - kSandbankTopRadius) / span, 0.0, 1.0);
  gradient =
      (t > 0.0 && t < 1.0 && r > 0.0) ? (-6.0 * t * (1.0 - t) / span) * (d / r) : glm::dvec2(0.0);
  return 1.0 - t * t * (3.0 - 2.0 * t);
}

double slopeTerm(double z, double& dz) {
  const double clamped = std::clamp(z, -kSlopeLimit, kSlopeLimit);
  dz = (z > -kSlopeLimit && z < kSlopeLimit) ? kSlopePerMetre : 0.0;
  return kSlopePerMetre * clamped;
}

// Height and gradient together so the two can never disagree.
double evaluate(double x, double z, glm::dvec2& gradient) {
  const glm::dvec2 p(x, z);
  double h = kSeabedBaseDepth;
  double dSlope = 0.0;
  h += slopeTerm(z, dSlope);
  gradient = glm::dvec2(0.0, dSlope);

  double dunes = 0.0;
  glm::dvec2 dDunes(0.0);
  for (const DuneTrain& d : kDunes) {
    const glm::dvec2 k = direction(d.directionDeg) * (kTwoPi / d.wavelength);
    const double phase = glm::dot(k, p) + d.phase;
    dunes += d.amplitude * std::sin(phase);
    dDunes += d.amplitude * std::cos(phase) * k;
  }
  glm::dvec2 dBank;
  const double bank = sandbankShare(p, dBank);
  const double duneScale = 1.0 - kSandbankDuneDamping * bank;
  h += duneScale * dunes + kSandbankLift * bank;
  gradient += duneScale * dDunes + (kSandbankLift - kSandbankDuneDamping * dunes) * dBank;

  const double r = glm::length(p);
  double dFade = 0.0;
  const double fade = rippleFade(r, dFade);
  if (fade > 0.0) {
    const double warpArg = glm::dot(kRippleWarpFrequency, p) + kRippleWarpPhase;
    const double warp = kRippleWarpAmplitude * std::sin(warpArg);
    const glm::dvec2 dWarp = kRippleWarpAmplitude * std::cos(warpArg) * kRippleWarpFrequency;
    const double k = kTwoPi / kRippleWavelength;
    const glm::dvec2 dir = direction(kRippleDirectionDeg);
    const double phase = k * (glm::dot(dir, p) + warp);
    const glm::dvec2 dPhase = k * (dir + dWarp);
    h += kRippleAmplitude * fade * std::sin(phase);
    gradient += kRippleAmplitude * fade * std::cos(phase) * dPhase;
    if (r > 0.0) gradient += kRippleAmplitude * std::sin(phase) * dFade * (p / r);
  }
  return h;
}

}  // namespace

double seabedHeight(double x, double z) {
  glm::dvec2 unused;
  return evaluate(x, z, unused);
}

glm::dvec2 seabedGradient(double x, double z) {
  glm::dvec2 gradient;
  evaluate(x, z, gradient);
  return gradient;
}

glm::dvec3 seabedNormal(double x, double z) {
  const glm::dvec2 g = seabedGradient(x, z);
  return glm::normalize(glm::dvec3(-g.x, 1.0, -g.y));
}

double seabedGridCoordinate(int i, const SeabedMeshParams& params) {
  const int n = std::max(params.resolution, 2);
  const double halfExtent = params.halfExtent;
  const double u = 2.0 * static_cast<double>(i) / static_cast<double>(n - 1) - 1.0;
  // x(u) = c*u + (H - c)*u^5: slope c at the centre (so spacing = centreSpacing there),
  // monotonic, and x(+-1) = +-H exactly.
  const double c =
      std::clamp(params.centreSpacing * static_cast<double>(n - 1) * 0.5, 0.0, halfExtent);
  const double u2 = u * u;
  return c * u + (halfExtent - c) * u2 * u2 * u;
}

Mesh buildSeabedMesh(const SeabedMeshParams& params) {
  Mesh mesh;
  mesh.name = "seabed";
  const int n = std::max(params.resolution, 2);
  std::vector<double> coord(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) coord[static_cast<std::size_t>(i)] = seabedGridCoordinate(i, params);
  const auto count = static_cast<std::size_t>(n) * static_cast<std::size_t>(n);
  mesh.positions.reserve(count);
  mesh.normals.reserve(count);
  // Row-major with x fastest: vertex (i, j) is at index j * n + i, x = coord[i], z = coord[j].
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const double x = coord[static_cast<std::size_t>(i)];
      const double z = coord[static_cast<std::size_t>(j)];
      glm::dvec2 gradient;
      const double y = evaluate(x, z, gradient);
      mesh.positions.emplace_back(static_cast<float>(x), static_cast<float>(y),
                                  static_cast<float>(z));
      mesh.normals.emplace_back(glm::normalize(glm::dvec3(-gradient.x, 1.0, -gradient.y)));
    }
  }
  const auto un = static_cast<std::uint32_t>(n);
  mesh.indices.reserve(static_cast<std::size_t>(n - 1) * static_cast<std::size_t>(n - 1) * 6);
  for (std::uint32_t j = 0; j + 1 < un; ++j) {
    for (std::uint32_t i = 0; i + 1 < un; ++i) {
      const std::uint32_t a = j * un + i, b = a + 1, c = a + un, d = c + 1;
      // (a, c, b) walks +z then +x, which is counter-clockwise seen from above.
      mesh.indices.insert(mesh.indices.end(), {a, c, b, b, c, d});
    }
  }
  return mesh;
}

}  // namespace ocean_scene
