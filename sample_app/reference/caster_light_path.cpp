#include "caster_light_path.h"

#include <algorithm>
#include <cmath>

#include <postfx/water/random.h>

#include "object_caustics_optics.h"

namespace ocean::reference {
namespace {

// Rays restart this far off the surface they leave (m): far above Embree's float precision at
// the few tens of metres of a frame, far below any caster's size.
constexpr double kOffset = 1e-4;

glm::dvec3 roughen(const glm::dvec3& d, double alpha, postfx::water::GaussianRandom& random) {
  if (!(alpha > 0.0)) return d;
  const glm::dvec3 ref = std::abs(d.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
  const glm::dvec3 a = glm::normalize(glm::cross(ref, d)), b = glm::cross(d, a);
  double g1 = 0.0, g2 = 0.0;
  random.nextPair(g1, g2);
  return glm::normalize(d + a * std::tan(alpha * g1) + b * std::tan(alpha * g2));
}

struct Path {
  glm::dvec3 from, dir;
  RayHit hit;
  glm::dvec3 weight;
  int channel = -1;     // >= 0: one channel of a dispersive glass, traced alone
  int insideMesh = -1;  // the solid caster the ray travels in, or -1
  int events = 0;
};

struct Walker {
  const EmbreeScene& scene;
  const CasterMaterials& materials;
  const CasterPathDesc& desc;
  postfx::water::GaussianRandom& random;
  const std::function<void(const CasterLanding&)>& land;

  // The next hit after leaving a surface at `point` along `dir` (skipping `skipMesh`, a
  // thin-walled caster the ray passes straight through).
  bool next(Path& p, const glm::dvec3& point, int skipMesh) const {
    p.from = point;
    for (int guard = 0; guard < 64; ++guard) {
      if (!scene.intersect(p.from, p.dir, 0.0, 1e30, p.hit)) return false;
      if (p.hit.mesh != skipMesh) return true;
      p.from += p.dir * (p.hit.t + kOffset);
    }
    return false;
  }

  void walk(Path p) const {
    while (p.events++ < desc.maxInteractions) {
      const glm::dvec3 x = p.from + p.dir * p.hit.t;
      if (!isCaster(materials, p.hit.mesh)) {
        // Inside a solid nothing lands: a surface through the glass is the host's problem.
        if (p.insideMesh < 0 && glm::dot(p.dir, p.hit.normal) < 0.0)
          land({x, p.hit.normal, p.weight, p.from});
        return;
      }
      const postfx::CasterMaterial& m = *materials[static_cast<size_t>(p.hit.mesh)];
      const bool entering = glm::dot(p.dir, p.hit.normal) < 0.0;
      const glm::dvec3 facing = entering ? p.hit.normal : -p.hit.normal;  // against the ray
      const double cosI = -glm::dot(p.dir, facing);
      const double alpha = double(m.roughness) * double(m.roughness);
      const double outer = x.y < desc.waterLevel ? desc.waterIor : 1.0;
      if (m.type == postfx::CasterMaterialType::Reflective) {
        if (!entering) return;  // inside a metal: nothing comes out
        const double c = 1.0 - std::clamp(cosI, 0.0, 1.0);
        const glm::dvec3 f0(m.reflectance);
        p.weight *= f0 + (glm::dvec3(1.0) - f0) * (c * c * c * c * c);
        p.dir = roughen(p.dir + 2.0 * cosI * facing, alpha, random);
        if (!(glm::dot(p.dir, facing) > 0.0)) return;  // roughened into the surface
        if (!next(p, x + facing * kOffset, -1)) return;
        continue;
      }
      if (m.thinWalled) {
        const double t = 1.0 - fresnel(cosI, double(m.ior) / outer);
        p.weight *= (t * t) * double(m.transmission) * glm::dvec3(m.tint);
        p.dir = roughen(p.dir, alpha, random);
        if (!next(p, x + p.dir * kOffset, p.hit.mesh)) return;
        continue;
      }
      if (entering && p.insideMesh < 0) {
        if (m.dispersion > 0.0f && p.channel < 0) {
          for (int c = 0; c < 3; ++c) {
            Path one = p;
            --one.events;  // this surface is met again by each channel
            one.channel = c;
            glm::dvec3 mask(0.0);
            mask[c] = 1.0;
            one.weight = p.weight * mask;
            walk(one);
          }
          return;
        }
        const double ior = channelIor(m, p.channel) / outer;
        const double t = 1.0 - fresnel(cosI, ior);
        const std::optional<glm::dvec3> in = refractRay(p.dir, facing, 1.0 / ior);
        if (!in) return;  // an index below the water's: reflected, not followed
        p.weight *= t * double(m.transmission) * glm::dvec3(m.tint);
        p.dir = glm::normalize(*in);
        p.insideMesh = p.hit.mesh;
        if (!next(p, x - facing * kOffset, -1)) return;
        continue;
      }
      if (entering || p.hit.mesh != p.insideMesh) return;  // overlapping casters: not followed
      // Leaving the solid: absorbed along the chord, then out, or back in by total reflection.
      p.weight *= glm::exp(-glm::dvec3(m.absorption) * p.hit.t);
      const double ior = channelIor(m, p.channel) / outer;
      const std::optional<glm::dvec3> out = refractRay(p.dir, facing, ior);
      if (!out) {
        p.dir = p.dir + 2.0 * cosI * facing;
        if (!next(p, x + facing * kOffset, -1)) return;
        continue;
      }
      p.weight *= 1.0 - fresnel(cosI, 1.0 / ior);
      p.dir = roughen(glm::normalize(*out), alpha, random);
      p.insideMesh = -1;
      if (!next(p, x - facing * kOffset, -1)) return;
    }
  }

  static double channelIor(const postfx::CasterMaterial& m, int channel) {
    const double ior = double(m.ior);
    if (channel < 0) return ior;
    return ior + double(channel - 1) * (ior - 1.0) * 0.025 * double(m.dispersion);
  }
};

}  // namespace

void followThroughCasters(const EmbreeScene& scene, const CasterMaterials& materials,
                          const CasterPathDesc& desc, const glm::dvec3& from, const glm::dvec3& dir,
                          const RayHit& hit, const glm::dvec3& weight,
                          postfx::water::GaussianRandom& random,
                          const std::function<void(const CasterLanding&)>& land) {
  if (!isCaster(materials, hit.mesh)) return;
  const Walker walker{scene, materials, desc, random, land};
  Path path;
  path.from = from;
  path.dir = dir;
  path.hit = hit;
  path.weight = weight;
  walker.walk(path);
}

}  // namespace ocean::reference
