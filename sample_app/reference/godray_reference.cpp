#include "godray_reference.h"

#include "godray_participation.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <thread>

namespace ocean::reference {
namespace {

// Mirrors of the shared shader math (shaders/postfx/seabed_caustics/postfx_caustics.h,
// postfx_godrays.h) and of postfx/src/seabed_caustics/caustics_constants.cpp, in double.
constexpr double kMaxSlope = 64.0;
constexpr double kSkyDistance = 65000.0;  // godrays_common.glsl

glm::dvec3 refract(const glm::dvec3& i, const glm::dvec3& n, double eta) {
  const double k = 1.0 - eta * eta * (1.0 - glm::dot(n, i) * glm::dot(n, i));
  if (k < 0.0) return glm::dvec3(0.0);
  return eta * i - (eta * glm::dot(n, i) + std::sqrt(k)) * n;
}

double omega(const glm::dvec3& ray, const glm::dvec3& reference, double tau) {
  const double a = std::clamp(glm::dot(ray, reference), -1.0, 1.0);
  return std::exp(-tau * a * a);
}

double causticFactor(const glm::dvec3& towardSun, const glm::dvec3& normal, double eta,
                     const glm::dvec3& reference, double tau, double reflectionWeight) {
  const glm::dvec3 incident = -towardSun;
  const glm::dvec3 refracted = refract(incident, normal, eta);
  const glm::dvec3 reflected = incident - 2.0 * glm::dot(normal, incident) * normal;
  const double t = omega(refracted, reference, tau), r = omega(reflected, reference, tau);
  return t + (r - t) * reflectionWeight;
}

glm::dvec3 waterNormal(glm::dvec2 slopes) {
  const double sx = std::abs(slopes.x) <= kMaxSlope ? slopes.x : 0.0;
  const double sz = std::abs(slopes.y) <= kMaxSlope ? slopes.y : 0.0;
  return glm::normalize(glm::dvec3(-sx, 1.0, -sz));
}

bool isSky(double depth, int convention) {
  if (!(depth == depth)) return true;
  return convention == 0 ? depth <= 0.0 : depth >= 1.0;
}

// Everything per frame, folded once.
struct Frame {
  int width = 0, height = 0, convention = 0;
  glm::dvec3 camera{0.0}, sun{0.0}, up{0.0}, reference{0.0};
  glm::dmat3 viewToWorld{1.0};
  glm::dmat4 projection{1.0}, lightClip{1.0};
  double level = 0.0, eta = 0.75, tau = 0.0, reflectionWeight = 0.0;
  double kx = 0.0, kz = 0.0, radiansPerPixel = 0.0, lodBias = 0.0;
  double surfaceFade = 0.0, depthFade = 0.0, maxDistance = 0.0;
  glm::dvec2 origin{0.0};
  int cascades = 1;
  double tile[postfx::kMaxCascades] = {};
  double log2TexelsPerMetre[postfx::kMaxCascades] = {};
  glm::dvec3 sigmaS{0.0}, sigmaT{0.0}, sunPath{0.0}, lightScale{0.0};
  bool shadow = false, shadowReverseZ = false, shadowNegOne = false;
  double shadowBias = 0.0;            // m toward the light
  glm::dvec3 towardShadowLight{0.0};  // the orthographic map's light (unit)
  bool footprintLod = true;
  glm::dvec3 gridX{1.0, 0.0, 0.0}, gridZ{0.0, 0.0, 1.0};  // godRayGrid(): x', z' plane normals
  double gridSpacing = 1.0;
};

Frame foldFrame(const postfx::CreateDesc& create, const postfx::FrameDesc& f,
                const GodRayInputs& in, bool footprintLod) {
  Frame r;
  r.width = in.width;
  r.height = in.height;
  r.convention = static_cast<int>(create.depthConvention);
  r.camera = f.camera.position;
  r.sun = glm::normalize(f.sun.direction);
  r.up = -refract(-r.sun, glm::dvec3(0.0, 1.0, 0.0), 1.0 / double(f.water.ior));
  const glm::dvec3 h(-r.sun.z, 0.0, r.sun.x);
  r.reference = glm::length(h) > 1e-9 ? h / glm::length(h) : glm::dvec3(1.0, 0.0, 0.0);
  r.viewToWorld = glm::transpose(glm::dmat3(glm::mat3(f.camera.view)));
  r.projection = f.camera.projection;
  r.level = f.water.level;
  const bool dispersion = postfx::hasFeature(create.features, postfx::Feature::Dispersion);
  r.eta = 1.0 / double(dispersion ? f.water.iorRgb.g : f.water.ior);
  r.tau = f.caustics.tau;
  r.reflectionWeight = f.caustics.reflectionWeight;
  r.kx = r.up.x / r.up.y;
  r.kz = r.up.z / r.up.y;
  r.radiansPerPixel = 2.0 / (std::abs(f.camera.projection[1][1]) * in.height);
  r.lodBias = f.caustics.lodBias;
  r.surfaceFade = f.godRays.surfaceFadeDistance;
  r.depthFade = f.godRays.depthFadeDistance;
  r.maxDistance = f.godRays.maxDistance;
  r.origin = f.water.origin;
  r.cascades = f.water.cascadeCount;
  for (int c = 0; c < r.cascades; ++c) {
    r.tile[c] = f.water.tileSize[c];
    r.log2TexelsPerMetre[c] = std::log2(std::max(in.water.width(), in.water.height()) / r.tile[c]);
  }
  r.sigmaS = glm::dvec3(f.water.scattering);
  r.sigmaT = glm::dvec3(f.water.absorption) + r.sigmaS;
  r.sunPath = r.sigmaT / std::max(r.up.y, 1e-3);
  r.lightScale = glm::dvec3(f.sun.irradiance) * double(f.godRays.intensity);
  r.shadow = postfx::hasFeature(create.features, postfx::Feature::ShadowMask) && !in.shadow.empty();
  r.lightClip = f.shadow.worldToLightClip;
  r.shadowReverseZ = f.shadow.depthConvention == postfx::DepthConvention::ReverseZ;
  r.shadowNegOne = f.shadow.depthConvention == postfx::DepthConvention::ForwardNegOneToOne;
  r.shadowBias = f.shadow.bias;
  // The map is orthographic here: clip x and y stay put along the light; growing depth leads
  // away from it unless reverse-Z (the plugin's shadowLight(), restated for the reference).
  const glm::dmat4& m = r.lightClip;
  glm::dvec3 axis = glm::normalize(
      glm::cross(glm::dvec3(m[0][0], m[1][0], m[2][0]), glm::dvec3(m[0][1], m[1][1], m[2][1])));
  if (glm::dot(axis, glm::dvec3(m[0][2], m[1][2], m[2][2])) < 0.0) axis = -axis;
  r.towardShadowLight = r.shadowReverseZ ? axis : -axis;
  r.footprintLod = footprintLod;
  r.gridX = r.reference;
  r.gridZ = glm::normalize(glm::cross(r.gridX, r.up));
  r.gridSpacing = f.godRays.gridSpacing;
  return r;
}

// S(t) of the header's model at world point p, t metres from the camera (per channel).
glm::dvec3 source(const Frame& f, const GodRayInputs& in, const glm::dvec3& p, double t) {
  const double depthBelow = f.level - p.y;
  double rho = godRayParticipation(depthBelow, f.surfaceFade, f.depthFade);
  if (!(rho > 0.0)) return glm::dvec3(0.0);
  if (f.shadow) {
    const glm::dvec4 clip = f.lightClip * glm::dvec4(p + f.towardShadowLight * f.shadowBias, 1.0);
    if (clip.w > 0.0) {
      const glm::dvec3 ndc = glm::dvec3(clip) / clip.w;
      if (std::abs(ndc.x) <= 1.0 && std::abs(ndc.y) <= 1.0) {
        const double ref = f.shadowNegOne ? ndc.z * 0.5 + 0.5 : ndc.z;
        rho *= in.shadow.visibility(glm::dvec2(ndc) * 0.5 + 0.5, std::clamp(ref, 0.0, 1.0),
                                    f.shadowReverseZ);
        if (!(rho > 0.0)) return glm::dvec3(0.0);
      }
    }
  }
  // Where this point's light entered the water: up the refracted sun to the level.
  const double above = p.y - f.level;
  const glm::dvec2 entry(p.x - f.origin.x - f.kx * above, p.z - f.origin.y - f.kz * above);
  const double logFootprint = std::log2(std::max(t * f.radiansPerPixel, 1e-6)) + f.lodBias;
  glm::dvec2 slopes(0.0);
  for (int c = 0; c < f.cascades; ++c) {
    const double lod = f.footprintLod ? logFootprint + f.log2TexelsPerMetre[c] : 0.0;
    slopes += glm::dvec2(in.water.sample(c, entry / f.tile[c], lod));
  }
  const double w =
      causticFactor(f.sun, waterNormal(slopes), f.eta, f.reference, f.tau, f.reflectionWeight);
  return rho * w * glm::exp(-f.sunPath * depthBelow);
}

// integral_a^b exp(-s (t - t0)) dt, with its limit b - a as s -> 0.
double segmentTransmittance(double s, double a, double b, double t0) {
  const double x = s * (b - a);
  if (x < 1e-8) return (b - a) * std::exp(-s * (a - t0));
  return (std::exp(-s * (a - t0)) - std::exp(-s * (b - t0))) / s;
}

glm::dvec3 pixelLight(const Frame& f, const GodRayInputs& in, int x, int y, int samples,
                      GodRayPixelStats& stats) {
  const double depth = in.depth[static_cast<size_t>(y) * f.width + x];
  const glm::dvec2 ndc((x + 0.5) / f.width * 2.0 - 1.0, (y + 0.5) / f.height * 2.0 - 1.0);
  const glm::dmat4& p = f.projection;
  glm::dvec3 view;
  double distance = kSkyDistance;
  if (isSky(depth, f.convention)) {
    view =
        glm::normalize(glm::dvec3((ndc.x + p[2][0]) / p[0][0], (ndc.y + p[2][1]) / p[1][1], -1.0));
  } else {
    const double ndcZ = f.convention == 2 ? depth * 2.0 - 1.0 : depth;
    const double viewZ = -p[3][2] / (ndcZ + p[2][2]);
    const glm::dvec3 pos(-viewZ * (ndc.x + p[2][0]) / p[0][0], -viewZ * (ndc.y + p[2][1]) / p[1][1],
                         viewZ);
    distance = std::min(glm::length(pos), kSkyDistance);
    if (!(distance > 0.0)) return glm::dvec3(0.0);
    view = pos / glm::length(pos);
  }
  const glm::dvec3 d = f.viewToWorld * view;
  // godRayUnderwaterRange in double.
  const double levelRelative = f.level - f.camera.y;
  double t0 = 0.0, t1 = std::min(distance, f.maxDistance);
  const double tSurface = std::abs(d.y) > 1e-12 ? levelRelative / d.y : 1e300;
  if (levelRelative < 0.0) {
    if (!(d.y < 0.0)) return glm::dvec3(0.0);
    t0 = tSurface;
  } else if (d.y > 0.0) {
    t1 = std::min(t1, tSurface);
  }
  if (!(t1 > t0)) return glm::dvec3(0.0);
  const double dt = (t1 - t0) / samples;
  glm::dvec3 sum(0.0);
  double w0 = 0.0, w1 = 0.0, w2 = 0.0;  // moments of S (green) under the transmittance weight
  for (int i = 0; i < samples; ++i) {
    const double a = t0 + i * dt, b = a + dt, t = a + 0.5 * dt;
    const glm::dvec3 s = source(f, in, f.camera + d * t, t);
    glm::dvec3 weight;
    for (int c = 0; c < 3; ++c) weight[c] = segmentTransmittance(f.sigmaT[c], a, b, t0);
    w0 += weight.g;
    w1 += weight.g * s.g;
    w2 += weight.g * s.g * s.g;
    sum += s * weight;
  }
  if (w0 > 0.0) {
    stats.sourceMean = w1 / w0;
    stats.sourceStd = std::sqrt(std::max(w2 / w0 - stats.sourceMean * stats.sourceMean, 0.0));
  }
  stats.gridCrossings =
      (std::abs(glm::dot(d, f.gridX)) + std::abs(glm::dot(d, f.gridZ))) * (t1 - t0) / f.gridSpacing;
  return f.lightScale * f.sigmaS * sum;
}

// The plugin's own skip rules (api.cpp): god rays off, sun at or below the horizon.
bool skipped(const postfx::CreateDesc& create, const postfx::FrameDesc& frame) {
  return !postfx::hasFeature(create.features, postfx::Feature::GodRays) || !frame.godRays.enabled ||
         !(frame.sun.direction.y > 0.0);
}

}  // namespace

bool captureGodRayInputs(const postfx::CreateDesc& create, const postfx::FrameDesc& frame,
                         GodRayInputs& in, std::string& error) {
  in = GodRayInputs{};
  glGetTextureLevelParameteriv(frame.target.texture, 0, GL_TEXTURE_WIDTH, &in.width);
  glGetTextureLevelParameteriv(frame.target.texture, 0, GL_TEXTURE_HEIGHT, &in.height);
  in.depth.resize(static_cast<size_t>(in.width) * in.height);
  glGetTextureImage(frame.depth.texture, 0, GL_DEPTH_COMPONENT, GL_FLOAT,
                    static_cast<GLsizei>(in.depth.size() * sizeof(float)), in.depth.data());
  if (!in.water.read(frame.water.texture.texture, frame.water.cascadeCount, error)) return false;
  if (postfx::hasFeature(create.features, postfx::Feature::ShadowMask))
    in.shadow = ShadowDepth::readBack(frame.shadow.depth.texture);
  return true;
}

std::vector<glm::dvec3> renderGodRayReference(const postfx::CreateDesc& create,
                                              const postfx::FrameDesc& frame,
                                              const GodRayInputs& inputs,
                                              const GodRayReferenceOptions& options,
                                              std::vector<GodRayPixelStats>* stats) {
  std::vector<glm::dvec3> image(static_cast<size_t>(inputs.width) * inputs.height, glm::dvec3(0.0));
  if (stats) stats->assign(image.size(), GodRayPixelStats{});
  if (skipped(create, frame) || image.empty()) return image;
  const Frame f = foldFrame(create, frame, inputs, options.footprintLod);
  const int samples = std::max(options.samples, 1);
  const int threads =
      std::max(1, options.threads > 0 ? options.threads
                                      : static_cast<int>(std::thread::hardware_concurrency()));
  // Rows are dealt out one at a time; each pixel depends on nothing else, so the result does not
  // depend on the thread count or the order.
  std::atomic<int> nextRow{0}, rowsDone{0};
  auto work = [&](bool reporter) {
    int reported = 0;
    for (int y = nextRow++; y < f.height; y = nextRow++) {
      for (int x = 0; x < f.width; ++x) {
        const size_t i = static_cast<size_t>(y) * f.width + x;
        GodRayPixelStats pixel;
        image[i] = pixelLight(f, inputs, x, y, samples, pixel);
        if (stats) (*stats)[i] = pixel;
      }
      const int done = ++rowsDone;
      if (reporter && options.progress && done * 10 / f.height > reported) {
        reported = done * 10 / f.height;
        std::fprintf(stderr, "god-ray reference (%dx%d, %d samples/pixel): %d%%\n", f.width,
                     f.height, samples, reported * 10);
      }
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(work, false);
  work(true);
  for (std::thread& t : pool) t.join();
  if (options.progress)
    std::fprintf(stderr, "god-ray reference (%dx%d, %d samples/pixel): done\n", f.width, f.height,
                 samples);
  return image;
}

double relativeRmse(const std::vector<glm::vec4>& image, const std::vector<glm::dvec3>& ref) {
  std::vector<glm::dvec3> rgb(image.size());
  for (size_t i = 0; i < image.size(); ++i) rgb[i] = glm::dvec3(glm::vec3(image[i]));
  return relativeRmse(rgb, ref);
}

double relativeRmse(const std::vector<glm::dvec3>& a, const std::vector<glm::dvec3>& ref) {
  double error = 0.0, norm = 0.0;
  for (size_t i = 0; i < a.size() && i < ref.size(); ++i) {
    const glm::dvec3 d = a[i] - ref[i];
    error += glm::dot(d, d);
    norm += glm::dot(ref[i], ref[i]);
  }
  return norm > 0.0 ? std::sqrt(error / norm) : (error > 0.0 ? HUGE_VAL : 0.0);
}

}  // namespace ocean::reference
