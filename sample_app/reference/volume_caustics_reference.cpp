#include "volume_caustics_reference.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <mutex>
#include <optional>
#include <random>
#include <thread>

#include "godray_participation.h"
#include "object_caustics_optics.h"

namespace ocean::reference {
namespace {

// Metres of the straight way from height ya to height yb (relative to the level) under water.
double submerged(double length, double ya, double yb) {
  const double below = std::max(-ya, 0.0) + std::max(-yb, 0.0);
  return length * std::min(below / std::max(std::abs(ya - yb), 1e-30), 1.0);
}

struct Segment {
  glm::dvec3 start, end, power;
  glm::dvec3 entry;  // where the ray entered the sphere
};

// One ray `d` from `o` through the sphere to the floor; nothing when it misses either.
std::optional<Segment> traceRay(const SphereCaster& s, const glm::dvec3& o, const glm::dvec3& d,
                                double planeY) {
  const std::optional<SphereCrossing> x = crossSphere(s.centre, s.radius, s.ior, o, d);
  if (!x || !x->refracted || !(x->out.y < -1e-12)) return std::nullopt;
  const double t = (planeY - x->exit.y) / x->out.y;
  if (!(t > 0.0)) return std::nullopt;
  return Segment{x->exit, x->exit + x->out * t,
                 x->entryTransmittance * x->exitTransmittance * s.transmission * s.tint *
                     glm::exp(-s.absorption * x->chord),
                 x->entry};
}

}  // namespace

std::vector<glm::dvec3> renderVolumeCausticReference(const SphereCaster& sphere, double planeY,
                                                     const VolumeCausticMedium& m,
                                                     const VolumeCausticCamera& cam,
                                                     int raysPerSide, unsigned seed,
                                                     bool progress) {
  const int w = cam.width, h = cam.height, n = raysPerSide;
  std::vector<glm::dvec3> image(size_t(w) * size_t(h), glm::dvec3(0.0));
  const std::optional<glm::dvec3> refracted =
      refractRay(-glm::normalize(m.towardSun), glm::dvec3(0.0, 1.0, 0.0), 1.0 / m.waterIor);
  if (!refracted || n < 1 || w < 1 || h < 1) return image;
  const glm::dvec3 d = glm::normalize(*refracted);
  const double cosT = std::max(-d.y, 1e-3);
  const glm::dvec3 ref = std::abs(d.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
  const glm::dvec3 right = glm::normalize(glm::cross(ref, d)), up = glm::cross(d, right);
  const double half = sphere.radius * 1.01, cell = 2.0 * half / n;
  const glm::dvec3 start = sphere.centre - d * (4.0 * sphere.radius);
  const glm::dmat3 worldToView = glm::transpose(cam.viewToWorld);
  const double radiansPerPixel = 2.0 / (cam.p11 * h);
  const double pixelArea = (2.0 / (cam.p00 * w)) * (2.0 / (cam.p11 * h));  // on the z = -1 plane
  std::mutex merge;
  const int threads = 2;
  auto work = [&](int thread) {
    std::vector<glm::dvec3> local(image.size(), glm::dvec3(0.0));
    for (int j = thread; j < n; j += threads) {
      if (progress && thread == 0 && (j % (n / 10 + 1)) == 0)
        std::fprintf(stderr, "[volume reference] %d%%\n", 100 * j / n);
      std::mt19937_64 rng(0x70bea5ULL + static_cast<unsigned long long>(j) +
                          (static_cast<unsigned long long>(seed) << 32));
      std::uniform_real_distribution<double> jitter(0.0, 1.0);
      for (int i = 0; i < n; ++i) {
        const double a = -half + (i + jitter(rng)) * cell;
        const double b = -half + (j + jitter(rng)) * cell;
        const glm::dvec3 o = start + right * a + up * b;
        const std::optional<Segment> seg = traceRay(sphere, o, d, planeY);
        if (!seg) continue;
        // The light's water path from the surface to where the ray entered the sphere.
        const double toEntry = std::max(m.waterLevel - seg->entry.y, 0.0) / cosT;
        const glm::dvec3 power = seg->power * m.sunIrradiance * (cell * cell) *
                                 glm::exp(-m.sigmaT * toEntry) * m.sigmaS * m.phase;
        const glm::dvec3 along = seg->end - seg->start;
        const double length = glm::length(along);
        if (!(length > 0.0)) continue;
        const glm::dvec3 e = along / length;
        double s = 0.0;
        while (s < length) {
          const glm::dvec3 mid0 = seg->start + e * s - cam.position;
          const double footprint = std::max(glm::length(mid0) * radiansPerPixel, 1e-5);
          const double ds = std::min(0.5 * footprint, length - s);
          const glm::dvec3 q = seg->start + e * (s + 0.5 * ds);
          const double qa = s + 0.5 * ds;
          s += ds;
          const double depthBelow = m.waterLevel - q.y;
          const double rho = godRayParticipation(depthBelow, m.surfaceFade, m.depthFade);
          if (!(rho > 0.0)) continue;
          const glm::dvec3 rel = q - cam.position;
          const glm::dvec3 v = worldToView * rel;
          if (!(-v.z > 1e-3)) continue;
          const double nx = (cam.p00 * v.x + cam.p20 * v.z) / -v.z;
          const double ny = (cam.p11 * v.y + cam.p21 * v.z) / -v.z;
          const double px = (nx * 0.5 + 0.5) * w, py = (ny * 0.5 + 0.5) * h;
          if (!(px >= 0.0 && px < w && py >= 0.0 && py < h)) continue;
          const size_t pixel = size_t(int(py)) * size_t(w) + size_t(int(px));
          const double t = glm::length(rel);
          if (!(t <= cam.distance[pixel] && t <= m.maxDistance)) continue;
          // The pixel's solid angle: its area on the z = -1 plane times cos^3 off the axis.
          const double cx = ((std::floor(px) + 0.5) / w * 2.0 - 1.0 + cam.p20) / cam.p00;
          const double cy = ((std::floor(py) + 0.5) / h * 2.0 - 1.0 + cam.p21) / cam.p11;
          const double cosPsi = 1.0 / std::sqrt(cx * cx + cy * cy + 1.0);
          const double omega = pixelArea * cosPsi * cosPsi * cosPsi;
          const double lightPath = submerged(qa, seg->start.y - m.waterLevel, q.y - m.waterLevel);
          const double viewPath = submerged(t, cam.position.y - m.waterLevel, q.y - m.waterLevel);
          local[pixel] +=
              power * rho * ds / (omega * t * t) * glm::exp(-m.sigmaT * (lightPath + viewPath));
        }
      }
    }
    std::lock_guard<std::mutex> lock(merge);
    for (size_t k = 0; k < image.size(); ++k) image[k] += local[k];
  };
  std::vector<std::thread> pool;
  for (int t = 0; t < threads; ++t) pool.emplace_back(work, t);
  for (std::thread& th : pool) th.join();
  if (progress) std::fprintf(stderr, "[volume reference] 100%%\n");
  return image;
}

}  // namespace ocean::reference
