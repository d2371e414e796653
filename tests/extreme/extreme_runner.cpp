#include "extreme_runner.h"
#include <postfx/testing.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <postfx/water/initial_spectrum.h>
#include <postfx/water/ocean.h>

#include "postfx_scene.h"
#include "postfx_test_util.h"

namespace extreme {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr float kSunIrradiance = 2.0f;  // E0, host HDR units
constexpr int kWidth = 64, kHeight = 36;
constexpr int kWaterSize = 32, kWaterLayers = 2;
constexpr double kWaterTiles[] = {40.0, 10.0};

postfx::Feature features(Pass pass) {
  using postfx::Feature;
  switch (pass) {
    case Pass::Caustics:
      return postfxtest::kRaw;
    case Pass::CausticsDispersion:  // with the other optional lookup path, tri-planar walls
      return postfxtest::kRaw | Feature::Dispersion | Feature::TriplanarWalls;
    case Pass::CausticsShadow:
      return postfxtest::kRaw | Feature::ShadowMask;
    default:
      return Feature::GodRays | Feature::ShadowMask;
  }
}

float badFloat(BadValue v) {
  switch (v) {
    case BadValue::NaN:
      return std::numeric_limits<float>::quiet_NaN();
    case BadValue::PosInf:
      return std::numeric_limits<float>::infinity();
    case BadValue::NegInf:
      return -std::numeric_limits<float>::infinity();
    case BadValue::Zero:
      return 0.0f;
  }
  return 0.0f;
}

// One texel in five is broken, spread over the whole image (no row or column is spared).
bool brokenTexel(int x, int y) {
  return (x + 3 * y) % 5 == 0;
}

template <typename Texel>
void breakTexels(std::vector<Texel>& texels, int width, int height, float value) {
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      if (brokenTexel(x, y)) texels[static_cast<size_t>(y * width + x)] = Texel(value);
}

std::vector<float> readDepth(GLuint texture, int w, int h) {
  std::vector<float> texels(static_cast<size_t>(w * h));
  glGetTextureImage(texture, 0, GL_DEPTH_COMPONENT, GL_FLOAT,
                    static_cast<GLsizei>(texels.size() * 4), texels.data());
  return texels;
}

// Returns what the texture holds where a broken value was written: depth uploads may clamp.
float breakDepth(GLuint texture, int w, int h, float value) {
  std::vector<float> texels = readDepth(texture, w, h);
  breakTexels(texels, w, h, value);
  glTextureSubImage2D(texture, 0, 0, 0, w, h, GL_DEPTH_COMPONENT, GL_FLOAT, texels.data());
  return readDepth(texture, w, h)[0];  // texel (0, 0) is a broken one
}

GLuint makeRgba16f(const std::vector<glm::vec4>& texels, int w, int h) {
  GLuint t = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &t);
  glTextureStorage2D(t, 1, GL_RGBA16F, w, h);
  glTextureSubImage2D(t, 0, 0, 0, w, h, GL_RGBA, GL_FLOAT, texels.data());
  return t;
}

// Shadow map in the forward [0,1] convention: an occluder (depth 0) over world x < x0 - 2 m,
// open (depth 1) elsewhere; light clip = ((x - x0) / 50, (z - z0) / 50, 0.5).
GLuint makeShadowMap(Input bad, BadValue value) {
  const int size = 32;
  std::vector<float> texels(size * size);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) texels[y * size + x] = x < size / 2 - 1 ? 0.0f : 1.0f;
  if (bad == Input::ShadowMap) breakTexels(texels, size, size, badFloat(value));
  GLuint t = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &t);
  glTextureStorage2D(t, 1, GL_DEPTH_COMPONENT32F, size, size);
  glTextureSubImage2D(t, 0, 0, 0, size, size, GL_DEPTH_COMPONENT, GL_FLOAT, texels.data());
  return t;
}

// The synthetic water's slope-field bounds (postfxtest::makeWaterTexture: per layer c two plane
// waves k1 = (2 + c, 1), k2 = (-1, 3 + c) cycles per tile, slopes A 2 pi k cos(.) per tile
// length). sup |grad s| <= A (2 pi)^2 sum |k|^2 / L; bilinear filtering of its samples can add
// at most sqrt(2) (each partial derivative is a mix of one-axis finite differences).
void syntheticWaterFacts(double amplitude, Facts& f) {
  double gradient = 0.0;
  for (int c = 0; c < kWaterLayers; ++c) {
    const glm::dvec2 k1(2 + c, 1), k2(-1, 3 + c);
    gradient +=
        amplitude * kTwoPi * kTwoPi * (glm::dot(k1, k1) + glm::dot(k2, k2)) / kWaterTiles[c];
  }
  f.slopeGradient = std::sqrt(2.0) * gradient;
}

// The same bounds for the water module's texture from its spectrum: a mode's complex height is
// a e^{-iwt} + b e^{iwt}, so |h| <= |a| + |b|, |slope| <= |k|(|a| + |b|), |grad slope| <=
// |k|^2 (|a| + |b|) and |d slope/dt| <= w |k| (|a| + |b|).
struct SpectrumBounds {
  double slope[4] = {}, height[4] = {}, gradient[4] = {}, rate[4] = {}, chop[4] = {};
};
SpectrumBounds spectrumBounds(const postfx::water::OceanDesc& desc) {
  const postfx::water::InitialSpectrum s = postfx::water::buildInitialSpectrum(desc);
  SpectrumBounds b;
  const int n = s.resolution;
  for (int c = 0; c < s.cascadeCount; ++c) {
    const double dk = kTwoPi / desc.tileSize[c];
    for (int m = 0; m < n; ++m) {
      for (int i = 0; i < n; ++i) {
        const size_t idx = s.index(c, i, m);
        const double amp = std::abs(s.a[idx]) + std::abs(s.b[idx]);
        const double k = dk * std::hypot(postfx::water::signedFrequency(i, n),
                                         postfx::water::signedFrequency(m, n));
        const double w = kTwoPi * s.cycles[idx] / desc.loopPeriod;
        b.height[c] += amp;
        b.slope[c] += k * amp;
        b.gradient[c] += k * k * amp;
        b.rate[c] += w * k * amp;
        b.chop[c] += desc.choppiness * k * amp;
      }
    }
  }
  return b;
}

postfx::water::OceanDesc oceanDesc() {
  postfx::water::OceanDesc desc;
  desc.resolution = 32;
  return desc;
}

}  // namespace

struct Runner::State {
  postfxtest::ContextPtr fx;
  std::unique_ptr<postfx::water::Ocean> ocean;
  SpectrumBounds spectrum;
};

Runner::Runner(Pass pass) : pass_(pass), state_(std::make_unique<State>()) {
  if (pass != Pass::Water) state_->fx = postfxtest::makeContext(features(pass));
  state_->spectrum = spectrumBounds(oceanDesc());
}

Runner::~Runner() = default;

namespace {

// Water pass: every mip level of the slope texture, each texel with its cascade's bounds.
Output runWater(postfx::water::Ocean& ocean, const SpectrumBounds& sb, double time) {
  Output out;
  std::string error;
  if (ocean.update(time, error) != postfx::water::Result::Ok) {
    out.error = error;
    return out;
  }
  const int n = ocean.resolution(), layers = ocean.cascadeCount();
  for (int level = 0, side = n; side >= 1; ++level, side /= 2) {
    std::vector<glm::vec4> texels(static_cast<size_t>(side) * side * layers);
    glGetTextureImage(ocean.slopeTexture(), level, GL_RGBA, GL_FLOAT,
                      static_cast<GLsizei>(texels.size() * sizeof(glm::vec4)), texels.data());
    for (size_t t = 0; t < texels.size(); ++t) {
      const int c = static_cast<int>(t / (static_cast<size_t>(side) * side));
      out.light.push_back(texels[t]);
      // Jacobian (1 + Dxx)(1 + Dzz) - Dxz^2 with |D..| <= chop: |J| <= (1 + chop)^2 + chop^2.
      const double chop = sb.chop[c];
      out.texelBound.push_back(glm::vec4(float(sb.slope[c]), float(sb.slope[c]),
                                         float(sb.height[c]),
                                         float((1.0 + chop) * (1.0 + chop) + chop * chop)));
      out.texelRate.push_back(float(sb.rate[c]));
    }
  }
  return out;
}

}  // namespace

Output Runner::run(const Knobs& k) {
  if (pass_ == Pass::Water) {
    if (!state_->ocean) {
      std::string error;
      if (postfx::water::Ocean::create(oceanDesc(), state_->ocean, error) !=
          postfx::water::Result::Ok) {
        Output out;
        out.error = error;
        return out;
      }
    }
    return runWater(*state_->ocean, state_->spectrum, k.oceanTime);
  }
  Output out;
  Facts& facts = out.facts;
  const glm::dvec3 offset = k.worldOffset;
  const double level = offset.y;

  postfxtest::SceneSpec spec;
  spec.width = kWidth;
  spec.height = kHeight;
  spec.camera = glm::dvec3(offset.x, level - k.cameraBelowLevel, offset.z);
  spec.lookDirection = k.lookDirection;
  spec.floorY = level - k.floorBelowLevel;
  spec.floorY2 = spec.floorY;
  spec.sphere = k.sphere;
  spec.sphereCenter = {1.5, -2.2, -6.0};  // camera-relative
  spec.sphereRadius = 1.25;
  spec.normalEncoding = k.badInput == Input::Normal ? 1 : 0;  // float normals can hold NaN/Inf
  postfxtest::Scene scene(spec);
  if (spec.normalEncoding != 0) {
    // The context was made for octahedral normals: rebuild it for this encoding.
    state_->fx = postfxtest::makeContext(features(pass_), 0, 1);
  }

  // Host inputs, broken where the row says.
  const bool useOcean = k.oceanTime >= 0.0;
  GLuint water = 0;
  if (useOcean) {
    std::string error;
    if ((!state_->ocean && postfx::water::Ocean::create(oceanDesc(), state_->ocean, error) !=
                               postfx::water::Result::Ok) ||
        state_->ocean->update(k.oceanTime, error) != postfx::water::Result::Ok) {
      out.error = "water module: " + error;
      return out;
    }
  } else {
    water = postfxtest::makeWaterTexture(kWaterSize, kWaterLayers, k.waterAmplitude);
    if (k.badInput == Input::WaterTexture) {
      std::vector<glm::vec4> texels(static_cast<size_t>(kWaterSize * kWaterSize * kWaterLayers));
      glGetTextureImage(water, 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(texels.size() * 16),
                        texels.data());
      breakTexels(texels, kWaterSize, kWaterSize * kWaterLayers, badFloat(k.badValue));
      glTextureSubImage3D(water, 0, 0, 0, 0, kWaterSize, kWaterSize, kWaterLayers, GL_RGBA,
                          GL_FLOAT, texels.data());
      glGenerateTextureMipmap(water);
    }
  }
  if (k.badInput == Input::Depth) {
    const float stored = breakDepth(scene.depth, kWidth, kHeight, badFloat(k.badValue));
    out.note = "broken depth texels hold " + std::to_string(stored);
  }
  if (k.badInput == Input::Normal) {
    std::vector<glm::vec4> normals = postfxtest::readRgba(scene.normal, kWidth, kHeight);
    breakTexels(normals, kWidth, kHeight, badFloat(k.badValue));
    glTextureSubImage2D(scene.normal, 0, 0, 0, kWidth, kHeight, GL_RGBA, GL_FLOAT, normals.data());
  }
  std::vector<glm::vec4> albedo(static_cast<size_t>(kWidth * kHeight), glm::vec4(1.0f));
  if (k.badInput == Input::Albedo) breakTexels(albedo, kWidth, kHeight, badFloat(k.badValue));
  const GLuint albedoTexture = makeRgba16f(albedo, kWidth, kHeight);
  const GLuint shadow = makeShadowMap(k.badInput, k.badValue);

  postfx::FrameDesc frame = postfxtest::makeFrame(scene, water, kWaterLayers, {}, level);
  frame.albedo = {albedoTexture, GL_RGBA16F};
  const double e = glm::radians(k.sunElevationDeg), az = glm::radians(k.sunAzimuthDeg);
  frame.sun.direction = {std::cos(e) * std::cos(az), std::sin(e), std::cos(e) * std::sin(az)};
  const float irradiance =
      k.irradianceBySine ? kSunIrradiance * float(std::max(std::sin(e), 0.0)) : kSunIrradiance;
  frame.sun.irradiance = glm::vec3(irradiance);
  frame.water.origin = {offset.x + 3.0, offset.z - 7.0};
  frame.water.ior = k.ior;
  frame.water.iorRgb = k.ior * glm::vec3(1.0f, 1.0015f, 1.0038f);
  frame.water.absorption = glm::vec3(k.absorption);
  frame.water.scattering = glm::vec3(k.scattering);
  if (useOcean) {
    frame.water.texture = {state_->ocean->slopeTexture(), GL_RGBA16F};
    frame.water.cascadeCount = state_->ocean->cascadeCount();
    for (int c = 0; c < frame.water.cascadeCount; ++c)
      frame.water.tileSize[c] = state_->ocean->tileSize(c);
  } else {
    for (int c = 0; c < kWaterLayers; ++c) frame.water.tileSize[c] = kWaterTiles[c];
  }
  frame.caustics.tau = k.tau;
  frame.caustics.reflectionWeight = k.reflectionWeight;
  frame.caustics.surfaceFadeDepth = k.surfaceFade;
  frame.godRays.surfaceFadeDistance = k.surfaceFade;
  frame.godRays.gridSpacing = k.gridSpacing;
  frame.godRays.sampleCount = k.sampleCount;
  frame.godRays.resolution =
      pass_ == Pass::GodRaysHalf ? postfx::GodRayResolution::Half : postfx::GodRayResolution::Full;
  postfx::testing::setGodRaySampling(
      *state_->fx, k.uniformSampling ? postfx::testing::GodRaySampling::UniformAlongRay
                                     : postfx::testing::GodRaySampling::WorldGrid);
  glm::dmat4 light(0.0);
  light[0][0] = 1.0 / 50.0;
  light[2][1] = 1.0 / 50.0;
  light[3][0] = -offset.x / 50.0;
  light[3][1] = -offset.z / 50.0;
  light[3][2] = 0.5;
  light[3][3] = 1.0;
  frame.shadow.depth = {shadow, GL_DEPTH_COMPONENT32F};
  frame.shadow.worldToLightClip = light;
  frame.shadow.depthConvention = postfx::DepthConvention::ForwardZeroToOne;

  scene.clearTarget(glm::vec4(0.0f));
  const postfx::Result result = postfx::dispatch(*state_->fx, frame);
  if (result != postfx::Result::Ok) out.error = postfx::lastError(state_->fx.get());
  out.light = postfxtest::readRgba(scene.target, kWidth, kHeight);
  if (isCausticPass(pass_))
    out.raw = postfxtest::readRed(postfx::testing::rawCausticTexture(*state_->fx), kWidth, kHeight);

  // The model's bounds. Caustics: albedo (sanitised to [0, 1]) * E * intensity. God rays: the
  // in-scatter of a homogeneous medium, E * intensity * sigma_s / sigma_t (0 without scattering).
  if (isCausticPass(pass_)) {
    out.bound = glm::vec3(irradiance * frame.caustics.intensity);
    out.fullScale = glm::vec3(kSunIrradiance * frame.caustics.intensity);
  } else {
    const glm::vec3 sigmaS = frame.water.scattering;
    const glm::vec3 sigmaT = frame.water.absorption + sigmaS;
    for (int c = 0; c < 3; ++c) {
      const float albedoS = sigmaT[c] > 0.0f ? sigmaS[c] / sigmaT[c] : 0.0f;
      out.bound[c] = irradiance * frame.godRays.intensity * albedoS;
      out.fullScale[c] = kSunIrradiance * frame.godRays.intensity * albedoS;
    }
  }

  // Facts for the continuity bounds.
  const double sinI = std::cos(e), sinT = sinI / double(k.ior);
  facts.cosRefracted = std::sqrt(std::max(1.0 - sinT * sinT, 0.0));
  facts.tanRefracted = sinT / std::max(facts.cosRefracted, 1e-300);
  facts.maxDepth = std::max(k.cameraBelowLevel, 0.0);
  facts.maxMarch = std::min<double>(frame.godRays.maxDistance, spec.farPlane);
  facts.width = kWidth;
  facts.height = kHeight;
  const glm::dmat3 viewToWorld = glm::transpose(glm::dmat3(scene.view));
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      const postfxtest::PixelTruth& t = scene.truth(x, y);
      if (t.hit != postfxtest::Hit::Sky)
        facts.maxDepth = std::max(facts.maxDepth, -(spec.camera.y + t.position.y - level));
      const glm::dvec3 view(((x + 0.5) / kWidth * 2.0 - 1.0) / scene.projection[0][0],
                            ((y + 0.5) / kHeight * 2.0 - 1.0) / scene.projection[1][1], -1.0);
      facts.rayUp.push_back(float(glm::normalize(viewToWorld * view).y));
      facts.hitDistance.push_back(t.hit == postfxtest::Hit::Sky
                                      ? float(facts.maxMarch)
                                      : float(std::min(glm::length(t.position), facts.maxMarch)));
    }
  }
  if (useOcean) {
    const SpectrumBounds& sb = state_->spectrum;
    for (int c = 0; c < frame.water.cascadeCount; ++c) {
      facts.slopeGradient += std::sqrt(2.0) * sb.gradient[c];
      facts.slopeRate += sb.rate[c];
    }
  } else {
    syntheticWaterFacts(k.waterAmplitude, facts);
  }

  const GLuint textures[] = {water, albedoTexture, shadow};
  glDeleteTextures(3, textures);
  return out;
}

}  // namespace extreme
