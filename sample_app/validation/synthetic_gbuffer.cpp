#include "synthetic_gbuffer.h"

#include <cmath>

#include <gbuffer/codec.h>

namespace ocean::validation {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

bool kept(const SyntheticSurface& surface, const glm::dvec3& p) {
  return glm::dot(glm::dvec3(surface.keep), p) + surface.keep.w >= 0.0;
}

// Ray parameters are in units of `dir`, the ray through the pixel at 1 m along the view axis, so
// a hit's parameter is its view distance.
double hitPlane(const SyntheticSurface& plane, const glm::dvec3& dir) {
  const double facing = glm::dot(dir, plane.normal);
  if (!(facing < 0.0)) return kInfinity;
  const double s = glm::dot(plane.point, plane.normal) / facing;
  return s > 0.0 ? s : kInfinity;
}

double hitSphere(const SyntheticSurface& sphere, const glm::dvec3& dir) {
  const glm::dvec3 oc = -sphere.point;
  const double a = glm::dot(dir, dir), b = glm::dot(oc, dir);
  const double c = glm::dot(oc, oc) - sphere.radius * sphere.radius;
  const double disc = b * b - a * c;
  if (!(disc > 0.0)) return kInfinity;
  const double s = (-b - std::sqrt(disc)) / a;
  return s > 0.0 ? s : kInfinity;
}

// The first crossing below the height field, marched along the unit ray to `maxDistance`
// (view distance) and bisected.
double hitHeightField(const SyntheticSurface& field, const glm::dvec3& dir, double maxDistance) {
  const double length = glm::length(dir);
  const glm::dvec3 unit = dir / length;
  const double maxT = std::min(maxDistance * length, 1e6);
  auto below = [&](double t) {
    const glm::dvec3 p = t * unit;
    return p.y < field.height(p.x, p.z);
  };
  double previous = 0.0;
  for (double t = 0.25; t < maxT; t += 0.25 + 0.02 * t) {
    if (below(t)) {
      double lo = previous, hi = t;
      for (int i = 0; i < 24; ++i) {
        const double mid = 0.5 * (lo + hi);
        (below(mid) ? hi : lo) = mid;
      }
      return hi / length;
    }
    previous = t;
  }
  return kInfinity;
}

glm::dvec3 heightFieldNormal(const SyntheticSurface& field, const glm::dvec3& p) {
  const double e = 1e-3;
  const double dx = (field.height(p.x + e, p.z) - field.height(p.x - e, p.z)) / (2.0 * e);
  const double dz = (field.height(p.x, p.z + e) - field.height(p.x, p.z - e)) / (2.0 * e);
  return glm::normalize(glm::dvec3(-dx, 1.0, -dz));
}

SyntheticPixel castPixel(const SyntheticScene& scene, const glm::dvec3& dir) {
  SyntheticPixel best;
  best.viewDistance = kInfinity;
  for (size_t i = 0; i < scene.surfaces.size(); ++i) {
    const SyntheticSurface& surface = scene.surfaces[i];
    double s = kInfinity;
    switch (surface.kind) {
      case SyntheticSurface::Kind::Plane:
        s = hitPlane(surface, dir);
        break;
      case SyntheticSurface::Kind::Sphere:
        s = hitSphere(surface, dir);
        break;
      case SyntheticSurface::Kind::HeightField:
        s = hitHeightField(surface, dir, scene.maxDistance);
        break;
    }
    if (!(s < best.viewDistance)) continue;
    const glm::dvec3 p = dir * s;
    if (!kept(surface, p)) continue;
    best.surface = int(i);
    best.position = p;
    best.viewDistance = s;
    switch (surface.kind) {
      case SyntheticSurface::Kind::Plane:
        best.normal = surface.normal;
        break;
      case SyntheticSurface::Kind::Sphere:
        best.normal = glm::normalize(p - surface.point);
        break;
      case SyntheticSurface::Kind::HeightField:
        best.normal = heightFieldNormal(surface, p);
        break;
    }
  }
  if (best.surface < 0 || !(best.viewDistance < scene.maxDistance)) return SyntheticPixel{};
  return best;
}

GLenum normalFormatFor(int encoding) {
  return encoding == 0 ? GL_RG16_SNORM : (encoding == 1 ? GL_RGBA16F : GL_RGBA8);
}

}  // namespace

double syntheticWindowDepth(double viewZ, const glm::dmat4& p, int convention) {
  const double ndc = (p[2][2] * viewZ + p[3][2]) / -viewZ;
  return convention == 2 ? ndc * 0.5 + 0.5 : ndc;
}

SyntheticGbuffer::SyntheticGbuffer(const SyntheticScene& scene)
    : width_(scene.width), normalFormat_(normalFormatFor(scene.normalEncoding)) {
  const int w = scene.width, h = scene.height;
  const size_t count = size_t(w) * size_t(h);
  const glm::dmat3 viewToWorld = glm::transpose(glm::dmat3(scene.view));
  const glm::vec4 skyNormal =
      gbuffer::shared::encodeNormal(glm::vec3(0, 1, 0), scene.normalEncoding);
  const double skyDepth = scene.depthConvention == 0 ? 0.0 : 1.0;
  pixels_.assign(count, SyntheticPixel{});
  std::vector<float> depthTexels(count, float(skyDepth));
  std::vector<glm::vec4> normalTexels(count, skyNormal), albedoTexels(count, scene.skyAlbedo);
  for (int y = 0; y < h && !scene.allSky; ++y) {
    for (int x = 0; x < w; ++x) {
      const size_t i = size_t(y) * size_t(w) + size_t(x);
      const double ndcX = (x + 0.5) / w * 2.0 - 1.0, ndcY = (y + 0.5) / h * 2.0 - 1.0;
      const glm::dvec3 dirView(ndcX / scene.projection[0][0], ndcY / scene.projection[1][1], -1.0);
      const SyntheticPixel hit = castPixel(scene, viewToWorld * dirView);
      if (hit.surface < 0) continue;
      pixels_[i] = hit;
      depthTexels[i] =
          float(syntheticWindowDepth(-hit.viewDistance, scene.projection, scene.depthConvention));
      const glm::vec3 n = scene.zeroNormals ? glm::vec3(0.0f) : glm::vec3(hit.normal);
      normalTexels[i] = gbuffer::shared::encodeNormal(n, scene.normalEncoding);
      albedoTexels[i] = glm::vec4(scene.surfaces[size_t(hit.surface)].albedo, 1.0f);
    }
  }
  const GLenum formats[4] = {GL_DEPTH_COMPONENT32F, normalFormat_, scene.albedoFormat,
                             scene.targetFormat};
  for (int t = 0; t < 4; ++t) {
    if (formats[t] == 0) continue;
    textures_[t] = glkit::createTexture(GL_TEXTURE_2D, {});
    glTextureStorage2D(textures_[t].id(), 1, formats[t], w, h);
  }
  glTextureSubImage2D(depth(), 0, 0, 0, w, h, GL_DEPTH_COMPONENT, GL_FLOAT, depthTexels.data());
  glTextureSubImage2D(normal(), 0, 0, 0, w, h, GL_RGBA, GL_FLOAT, normalTexels.data());
  glTextureSubImage2D(albedo(), 0, 0, 0, w, h, GL_RGBA, GL_FLOAT, albedoTexels.data());
  if (target()) {
    const glm::vec4 zero(0.0f);
    glClearTexImage(target(), 0, GL_RGBA, GL_FLOAT, &zero[0]);
  }
}

double SyntheticGbuffer::coverage() const {
  size_t hits = 0;
  for (const SyntheticPixel& p : pixels_) hits += p.surface >= 0 ? 1 : 0;
  return pixels_.empty() ? 0.0 : double(hits) / double(pixels_.size());
}

}  // namespace ocean::validation
