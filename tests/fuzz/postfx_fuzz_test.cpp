// Dispatch fuzz: a deterministic seed drives a few thousand frames, each a valid frame
// with one field group spoiled by wild values (IEEE specials, values at and past every bound,
// far magnitudes), in contexts that differ in depth convention, normal encoding and features.
// Every case must end one of two ways:
//   * a non-Ok Result with a message, the target bit-identical and GL state as the host left it;
//   * Ok with every added value finite and no GL error;
// and either way the next ordinary frame must be bit-identical to a fresh context's.
#include <gtest/gtest.h>
#include <postfx/testing.h>

#include <cstdio>
#include <cstring>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "fuzz_values.h"
#include "gl_fixture.h"
#include "postfx_gl_snapshot.h"
#include "postfx_object_caustics_util.h"

namespace {

using namespace postfxtest;
using postfx::Feature;
using postfx::Result;
using postfxfuzz::Rng;
using postfxfuzz::toFloat;
using postfxfuzz::wild;
using postfxfuzz::wildFloat;
using postfxfuzz::wildInt;
using postfxfuzz::wildInt64;

constexpr std::uint64_t kSeed = 0x15f0221;
constexpr int kCasesPerContext = 640;
constexpr int kCasterSlots = postfx::kMaxCasters + 8;  // casterCount up to 72 reads in bounds
const glm::vec4 kMarker(0.125f, 0.25f, 0.5f, 1.0f);

enum Group {
  kCamera,
  kSun,
  kWater,
  kShadow,
  kCaustics,
  kGodRays,
  kObjectSettings,
  kCasters,
  kTextureSlots,
  kGBufferTexels,
  kWaterTexels,
  kGroupCount
};
const char* const kGroupNames[kGroupCount] = {"camera",
                                              "sun",
                                              "water",
                                              "shadow",
                                              "caustics settings",
                                              "god rays",
                                              "object settings",
                                              "casters",
                                              "texture slots",
                                              "G-buffer texels",
                                              "water texels"};

struct Spec {
  const char* name;
  Feature features;
  int depthConvention, normalEncoding;
};

// Host-owned textures of every kind a host could pass by mistake, and names that are not.
struct TexturePool {
  std::vector<GLuint> textures;
  GLuint buffer = 0;
  TexturePool(int w, int h) {
    glCreateBuffers(1, &buffer);
    glNamedBufferStorage(buffer, 4096, nullptr, 0);
    auto make = [this](GLenum target, const std::function<void(GLuint)>& storage) {
      GLuint t = 0;
      glCreateTextures(target, 1, &t);
      storage(t);
      textures.push_back(t);
    };
    make(GL_TEXTURE_BUFFER, [this](GLuint t) { glTextureBuffer(t, GL_RGBA32F, buffer); });
    make(GL_TEXTURE_1D, [w](GLuint t) { glTextureStorage1D(t, 1, GL_RGBA16F, w); });
    make(GL_TEXTURE_3D, [w, h](GLuint t) { glTextureStorage3D(t, 1, GL_RGBA16F, w, h, 2); });
    make(GL_TEXTURE_CUBE_MAP, [h](GLuint t) { glTextureStorage2D(t, 1, GL_RGBA16F, h, h); });
    make(GL_TEXTURE_2D_MULTISAMPLE,
         [w, h](GLuint t) { glTextureStorage2DMultisample(t, 4, GL_RGBA16F, w, h, GL_TRUE); });
    make(GL_TEXTURE_2D, [w, h](GLuint t) { glTextureStorage2D(t, 1, GL_RGBA8, w, h); });
    make(GL_TEXTURE_2D, [w, h](GLuint t) { glTextureStorage2D(t, 1, GL_RGBA16F, w, h); });
    make(GL_TEXTURE_2D, [w, h](GLuint t) { glTextureStorage2D(t, 1, GL_RGBA16F, w + 1, h); });
    make(GL_TEXTURE_2D, [w, h](GLuint t) { glTextureStorage2D(t, 1, GL_DEPTH_COMPONENT16, w, h); });
    make(GL_TEXTURE_2D_ARRAY, [](GLuint t) { glTextureStorage3D(t, 1, GL_RGBA16F, 16, 16, 1); });
    make(GL_TEXTURE_2D, [](GLuint) {});  // no storage
  }
  ~TexturePool() {
    glDeleteTextures(static_cast<GLsizei>(textures.size()), textures.data());
    glDeleteBuffers(1, &buffer);
  }
  GLuint pick(Rng& r) const {
    switch (r.below(4)) {
      case 0:
        return 0;
      case 1:
        return static_cast<GLuint>(r.bits());  // almost surely not a name
      default:
        return textures[static_cast<size_t>(r.below(static_cast<int>(textures.size())))];
    }
  }
};

// A copy of a texture's level 0 to restore it bit for bit after texel fuzzing.
struct Pristine {
  GLuint source = 0, copy = 0;
  GLenum target = GL_TEXTURE_2D;
  int w = 0, h = 0, layers = 1;
  Pristine(GLuint texture, GLenum textureTarget) : source(texture), target(textureTarget) {
    GLint format = 0;
    glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_INTERNAL_FORMAT, &format);
    glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_WIDTH, &w);
    glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_HEIGHT, &h);
    if (target == GL_TEXTURE_2D_ARRAY)
      glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_DEPTH, &layers);
    glCreateTextures(target, 1, &copy);
    if (target == GL_TEXTURE_2D_ARRAY) {
      glTextureStorage3D(copy, 1, static_cast<GLenum>(format), w, h, layers);
    } else {
      glTextureStorage2D(copy, 1, static_cast<GLenum>(format), w, h);
    }
    glCopyImageSubData(source, target, 0, 0, 0, 0, copy, target, 0, 0, 0, 0, w, h, layers);
  }
  ~Pristine() { glDeleteTextures(1, &copy); }
  void restore() const {
    glCopyImageSubData(copy, target, 0, 0, 0, 0, source, target, 0, 0, 0, 0, w, h, layers);
  }
  // Writes `count` random texels of level 0 (layer 0) with wild floats.
  void spoil(Rng& r, int count, bool depth) const {
    for (int i = 0; i < count; ++i) {
      const int x = r.below(w), y = r.below(h);
      if (depth) {
        const float v = r.chance(0.5) ? wildFloat(r, 0.5f) : (r.chance(0.5) ? 0.0f : 1.0f);
        glTextureSubImage2D(source, 0, x, y, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &v);
      } else {
        float v[4];
        for (float& c : v) c = r.chance(0.5) ? wildFloat(r, 0.5f) : 0.0f;
        if (target == GL_TEXTURE_2D_ARRAY) {
          glTextureSubImage3D(source, 0, x, y, 0, 1, 1, 1, GL_RGBA, GL_FLOAT, v);
        } else {
          glTextureSubImage2D(source, 0, x, y, 1, 1, GL_RGBA, GL_FLOAT, v);
        }
      }
    }
  }
};

void spoilMatrix(Rng& r, glm::dmat4& m) {
  if (r.chance(0.7)) {
    m[r.below(4)][r.below(4)] = wild(r, 1.0);
  } else {
    m *= wild(r, 1.0);
  }
}

struct Outcome {
  int cases = 0, ok = 0;
  std::map<std::string, int> refused;  // by Result
  std::map<std::string, int> broken;   // by broken promise (cases, not values)
};

class PostfxFuzzTest : public testsupport::GlTest {
 protected:
  // The GL errors since the last call (debug messages of type error and glGetError), so that
  // the fuzz counts them per case instead of stopping at the first.
  static std::string takeGlErrors() {
    std::string errors;
    for (const auto& message : testsupport::glContext().debugLog().take())
      if (message.type == GL_DEBUG_TYPE_ERROR)
        errors += glcontext::debugMessageString(message) + "; ";
    for (GLenum e = glGetError(); e != GL_NO_ERROR; e = glGetError())
      errors += "glGetError " + std::to_string(e) + "; ";
    return errors;
  }
};

TEST_F(PostfxFuzzTest, EveryFrameIsRefusedCleanlyOrDrawnFinite) {
  const Spec specs[] = {
      {"reverse-Z, octahedral: caustics + god rays + shadow + raw + dispersion",
       Feature::Caustics | Feature::GodRays | Feature::ShadowMask |
           postfx::testing::RawCausticOutput | Feature::Dispersion,
       0, 0},
      {"forward [0,1], xyz: physical caustics + god rays + tri-planar walls",
       Feature::Caustics | Feature::GodRays | Feature::WavefrontAreaRatio | Feature::TriplanarWalls,
       1, 1},
      {"forward [-1,1], xyz UNORM: caustics + object caustics + floor",
       Feature::Caustics | Feature::ObjectCaustics | postfx::testing::BenchmarkFloor, 2, 2},
      {"reverse-Z, xyz: object caustics (dispersed glass) + their volume + god rays",
       Feature::ObjectCaustics | Feature::VolumeCaustics | Feature::GodRays | Feature::Dispersion,
       0, 1},
  };
  Rng rng(kSeed);
  Outcome outcomes[kGroupCount];
  int failures = 0;
  // One broken promise of one case: counted by kind under its group, the first few reported.
  auto fail = [&failures, &outcomes](Group group, const char* kind, const std::string& what) {
    ++outcomes[group].broken[kind];
    if (++failures <= 25) ADD_FAILURE() << what;
  };

  const GlMesh sphere = makeSphereMesh(0.8, 16, 8);
  const GlMesh cube = makeCubeMesh(0.5);
  for (const Spec& spec : specs) {
    SceneSpec sceneSpec = ObjectHost::defaultSpec();
    sceneSpec.width = 40;
    sceneSpec.height = 24;
    sceneSpec.depthConvention = spec.depthConvention;
    sceneSpec.normalEncoding = spec.normalEncoding;
    ObjectHost host(sunAt(25.0, 30.0), 4.0, sceneSpec);
    const int w = sceneSpec.width, h = sceneSpec.height;
    const GLuint water = makeWaterTexture(32, 3, 0.02);
    GLuint shadow = 0;
    glCreateTextures(GL_TEXTURE_2D, 1, &shadow);
    glTextureStorage2D(shadow, 1, GL_DEPTH_COMPONENT32F, 32, 32);
    const float one = 1.0f;
    glClearTexImage(shadow, 0, GL_DEPTH_COMPONENT, GL_FLOAT, &one);
    TexturePool pool(w, h);

    postfx::CreateDesc desc;
    desc.features = spec.features;
    desc.depthConvention = static_cast<postfx::DepthConvention>(spec.depthConvention);
    desc.normalEncoding = static_cast<postfx::NormalEncoding>(spec.normalEncoding);
    desc.maxWaterCascades = 3;
    desc.memoryBudgetMiB = 16;  // big maps and grids are refused up front: the fuzz stays fast
    postfx::Context* raw = nullptr;
    ASSERT_EQ(postfx::create(desc, raw), Result::Ok) << postfx::lastError(nullptr);
    ContextPtr fx(raw);  // the fuzzed context
    ASSERT_EQ(postfx::create(desc, raw), Result::Ok) << postfx::lastError(nullptr);
    ContextPtr fresh(raw);

    // The ordinary frame: everything under water, every pass of the context has work.
    std::vector<postfx::CasterMesh> baseCasters(kCasterSlots);
    for (int i = 0; i < kCasterSlots; ++i) {
      postfx::CasterMaterial material;
      if (i % 2 == 1) material.type = postfx::CasterMaterialType::Reflective;
      baseCasters[i] = (i % 2 == 0 ? sphere : cube)
                           .caster(translation({0.6 * (i % 2), 1.5, 0.2 * (i % 3)}), material);
    }
    postfx::ObjectCausticsSettings objectSettings;
    objectSettings.gridSize = 32;
    objectSettings.mapSize = 64;
    postfx::FrameDesc ordinary = host.frame(baseCasters.data(), 2, objectSettings);
    ordinary.water.texture = {water, GL_RGBA32F};
    ordinary.water.cascadeCount = 3;
    ordinary.water.level = 10.0;
    ordinary.shadow.depth = {shadow, GL_DEPTH_COMPONENT32F};
    ordinary.shadow.worldToLightClip = host.receivers.worldToLightClip;
    ordinary.shadow.depthConvention = postfx::DepthConvention::ForwardNegOneToOne;
    ordinary.godRays.sampleCount = 8;
    ordinary.caustics.gridResolution = 64;
    if (hasFeature(spec.features, Feature::WavefrontAreaRatio))
      ordinary.caustics.model = postfx::CausticsModel::WavefrontAreaRatio;

    auto run = [&](postfx::Context& context, const postfx::FrameDesc& frame, Result& r) {
      host.scene.clearTarget(kMarker);
      r = postfx::dispatch(context, frame);
      return readRgba(host.scene.target, w, h);
    };
    auto rawOutput = [&](postfx::Context& context) {
      const GLuint t = postfx::testing::rawCausticTexture(context);
      return t != 0 ? readRed(t, w, h) : std::vector<float>();
    };
    Result r = Result::InvalidArgument;
    const std::vector<glm::vec4> reference = run(*fresh, ordinary, r);
    ASSERT_EQ(r, Result::Ok) << spec.name << ": " << postfx::lastError(fresh.get());
    const std::vector<float> rawReference = rawOutput(*fresh);
    int lit = 0;
    for (const glm::vec4& v : reference) lit += v != kMarker ? 1 : 0;
    ASSERT_GT(lit, w * h / 4) << spec.name << ": the ordinary frame must add light";
    const postfx::FrameStats& freshStats = postfx::stats(*fresh);
    for (int p = 0; p < postfx::kPassCount; ++p) {
      EXPECT_FALSE(freshStats.passes[p].present && freshStats.passes[p].skipped)
          << spec.name << ": pass " << postfx::toString(postfx::Pass(p)) << " has work";
    }

    const Pristine depthCopy(host.scene.depth, GL_TEXTURE_2D),
        normalCopy(host.scene.normal, GL_TEXTURE_2D), albedoCopy(host.scene.albedo, GL_TEXTURE_2D),
        waterCopy(water, GL_TEXTURE_2D_ARRAY), shadowCopy(shadow, GL_TEXTURE_2D),
        receiverCopy(host.receivers.depth, GL_TEXTURE_2D);

    for (int n = 0; n < kCasesPerContext; ++n) {
      const Group group = static_cast<Group>(n % kGroupCount);
      postfx::FrameDesc f = ordinary;
      std::vector<postfx::CasterMesh> casters = baseCasters;
      f.objectCaustics.casters = casters.data();
      const Pristine* spoiled[2] = {nullptr, nullptr};
      const int edits = 1 + rng.below(2);
      // A third of the camera, sun and water cases run in clear water (no absorption): there a far
      // water level once reached the GPU as Inf and left NaN (Inf * 0) in the target.
      if ((group == kCamera || group == kSun || group == kWater) && rng.chance(1.0 / 3.0))
        f.water.absorption = glm::vec3(0.0f);
      for (int e = 0; e < edits; ++e) {
        switch (group) {
          case kCamera:
            switch (rng.below(3)) {
              case 0:
                f.camera.position[rng.below(3)] = wild(rng, f.camera.position[0] + 1.0);
                break;
              case 1:
                f.camera.view[rng.below(4)][rng.below(4)] = wildFloat(rng, 1.0f);
                break;
              default:
                spoilMatrix(rng, f.camera.projection);
            }
            break;
          case kSun:
            if (rng.chance(0.6)) {
              f.sun.direction[rng.below(3)] = wild(rng, f.sun.direction.y);
            } else if (rng.chance(0.5)) {
              f.sun.direction *= wild(rng, 1.0);
            } else {
              f.sun.irradiance[rng.below(3)] = wildFloat(rng, 2.0f);
            }
            break;
          case kWater:
            switch (rng.below(10)) {
              case 0:
                f.water.level = wild(rng, f.water.level);
                break;
              case 1:
                f.water.origin[rng.below(2)] = wild(rng, 0.0);
                break;
              case 2:
                f.water.cascadeCount = wildInt(rng, 3);
                break;
              case 3:
                f.water.tileSize[rng.below(4)] = wild(rng, 10.0);
                break;
              case 4:
                f.water.rmsLaplacian[rng.below(4)] = wild(rng, 0.5);
                break;
              case 5:
                f.water.longestWavelength[rng.below(4)] = wild(rng, 20.0);
                break;
              case 6:
                f.water.ior = wildFloat(rng, 1.333f);
                break;
              case 7:
                f.water.iorRgb[rng.below(3)] = wildFloat(rng, 1.333f);
                break;
              case 8:
                f.water.absorption[rng.below(3)] = wildFloat(rng, 0.1f);
                break;
              default:
                f.water.scattering[rng.below(3)] = wildFloat(rng, 0.03f);
            }
            break;
          case kShadow:
            switch (rng.below(3)) {
              case 0:
                spoilMatrix(rng, rng.chance(0.5) ? f.shadow.worldToLightClip
                                                 : f.objectCaustics.receivers.worldToLightClip);
                break;
              case 1:
                (rng.chance(0.5) ? f.shadow.depthConvention
                                 : f.objectCaustics.receivers.depthConvention) =
                    static_cast<postfx::DepthConvention>(wildInt(rng, 1));
                break;
              default:
                (rng.chance(0.5) ? f.shadow.bias : f.objectCaustics.receivers.bias) =
                    wildFloat(rng, 0.001f);
            }
            break;
          case kCaustics: {
            postfx::CausticsSettings& s = f.caustics;
            switch (rng.below(14)) {
              case 0:
                s.enabled = !s.enabled;
                break;
              case 1:
                s.tau = wildFloat(rng, s.tau);
                break;
              case 2:
                s.reflectionWeight = wildFloat(rng, 0.25f);
                break;
              case 3:
                s.intensity = wildFloat(rng, 1.0f);
                break;
              case 4:
                s.surfaceFadeDepth = wildFloat(rng, 1.0f);
                break;
              case 5:
                s.triplanarSharpness = wildFloat(rng, 8.0f);
                break;
              case 6:
                s.lodBias = wildFloat(rng, 0.0f);
                break;
              case 7:
                s.minCascadeContrast = wildFloat(rng, 0.1f);
                break;
              case 8:
                s.model = static_cast<postfx::CausticsModel>(wildInt(rng, 1));
                break;
              case 9:
                s.gridResolution = wildInt(rng, 64);
                break;
              case 10:
                s.windowSize = wildFloat(rng, 32.0f);
                break;
              case 11:
                s.depthLayers = wildInt(rng, 4);
                break;
              case 12:
                s.maxReceiverDepth = wildFloat(rng, 16.0f);
                break;
              default:
                s.maxIrradiance = wildFloat(rng, 32.0f);
            }
            break;
          }
          case kGodRays: {
            postfx::GodRaySettings& g = f.godRays;
            switch (rng.below(10)) {
              case 0:
                g.enabled = !g.enabled;
                break;
              case 1:
                g.sampleCount = wildInt(rng, 8);
                break;
              case 2:
                g.gridSpacing = wildFloat(rng, 0.75f);
                break;
              case 3:
                g.intensity = wildFloat(rng, 1.5f);
                break;
              case 4:
                g.surfaceFadeDistance = wildFloat(rng, 2.0f);
                break;
              case 5:
                g.depthFadeDistance = wildFloat(rng, 40.0f);
                break;
              case 6:
                g.maxDistance = wildFloat(rng, 60.0f);
                break;
              case 7:
                g.resolution = static_cast<postfx::GodRayResolution>(wildInt(rng, 2));
                break;
              case 8:
                g.dither = !g.dither;
                break;
              default:
                g.intensity = wildFloat(rng, 1.5f);
            }
            break;
          }
          case kObjectSettings: {
            postfx::ObjectCausticsSettings& s = f.objectCaustics.settings;
            switch (rng.below(11)) {
              case 0:
                s.enabled = !s.enabled;
                break;
              case 1:
                s.mapSize = wildInt(rng, 64);
                break;
              case 2:
                s.gridSize = wildInt(rng, 32);
                break;
              case 3:
                s.iterations = wildInt(rng, 1);
                break;
              case 4:
                s.exitIterations = wildInt(rng, 5);
                break;
              case 5:
                s.splatRadius = wildFloat(rng, 1.0f);
                break;
              case 6:
                s.footprintScale = wildFloat(rng, 2.0f);
                break;
              case 7:
                s.intensity = wildFloat(rng, 1.0f);
                break;
              case 8:
                s.temporalFilter = !s.temporalFilter;
                break;
              case 9:
                s.temporalWeight = wildFloat(rng, 0.5f);
                break;
              default:
                f.objectCaustics.casterCount = wildInt(rng, 2);
            }
            break;
          }
          case kCasters: {
            postfx::CasterMesh& m = casters[static_cast<size_t>(rng.below(2))];
            switch (rng.below(21)) {
              case 0:
                m.vertexCount = wildInt64(rng, m.vertexCount);
                break;
              case 1:
                m.indexCount = wildInt64(rng, m.indexCount);
                break;
              case 2:
                m.baseOffset = wildInt64(rng, 0);
                break;
              case 3:
                m.indexOffset = wildInt64(rng, 0);
                break;
              case 4:
                m.positionOffset = wildInt(rng, 0);
                break;
              case 5:
                m.normalOffset = wildInt(rng, 12);
                break;
              case 6:
                m.stride = wildInt(rng, 24);
                break;
              case 7:
                m.indexType = static_cast<postfx::IndexType>(wildInt(rng, GL_UNSIGNED_INT));
                break;
              case 8:
                (rng.chance(0.5) ? m.vertexBuffer : m.indexBuffer) =
                    rng.chance(0.5) ? static_cast<std::uint32_t>(rng.bits()) : pool.buffer;
                break;
              case 9:
                m.boundsMin[rng.below(3)] = wildFloat(rng, -1.0f);
                break;
              case 10:
                m.boundsMax[rng.below(3)] = wildFloat(rng, 1.0f);
                break;
              case 11:
                spoilMatrix(rng, m.modelToWorld);
                break;
              case 12:
                m.material.type = static_cast<postfx::CasterMaterialType>(wildInt(rng, 0));
                break;
              case 13:
                m.material.ior = wildFloat(rng, 1.5f);
                break;
              case 14:
                m.material.absorption[rng.below(3)] = wildFloat(rng, 0.0f);
                break;
              case 15:
                m.material.reflectance[rng.below(3)] = wildFloat(rng, 0.9f);
                break;
              case 16:
                m.material.transmission = wildFloat(rng, 0.5f);
                break;
              case 17:
                m.material.tint[rng.below(3)] = wildFloat(rng, 0.5f);
                break;
              case 18:
                m.material.roughness = wildFloat(rng, 0.5f);
                break;
              case 19:
                m.material.dispersion = wildFloat(rng, 1.0f);
                break;
              default:
                m.material.thinWalled = !m.material.thinWalled;
            }
            if (rng.chance(0.1)) f.objectCaustics.casters = nullptr;
            break;
          }
          case kTextureSlots: {
            postfx::TextureRef* slots[] = {&f.target,
                                           &f.depth,
                                           &f.normal,
                                           &f.albedo,
                                           &f.water.texture,
                                           &f.shadow.depth,
                                           &f.objectCaustics.receivers.depth};
            postfx::TextureRef& slot = *slots[rng.below(7)];
            if (rng.chance(0.3)) {
              slot.format =
                  static_cast<postfx::GlEnum>(wildInt(rng, static_cast<int>(slot.format)));
            } else {
              slot = {pool.pick(rng), 0};
            }
            break;
          }
          case kGBufferTexels: {
            const Pristine* copies[] = {&depthCopy, &normalCopy, &albedoCopy, &shadowCopy,
                                        &receiverCopy};
            const int which = rng.below(5);
            copies[which]->spoil(rng, 1 + rng.below(8), which == 0 || which >= 3);
            spoiled[e] = copies[which];
            break;
          }
          default: {  // water texels
            waterCopy.spoil(rng, 1 + rng.below(8), false);
            spoiled[e] = &waterCopy;
          }
        }
      }

      Outcome& outcome = outcomes[group];
      ++outcome.cases;
      const std::string where =
          std::string(spec.name) + " / " + kGroupNames[group] + " case " + std::to_string(n);
      takeGlErrors();
      const GlSnapshot before = snapshotGlState();
      const std::vector<glm::vec4> after = run(*fx, f, r);
      const std::string message = postfx::lastError(fx.get());
      if (r == Result::Ok) {
        ++outcome.ok;
        int bad = 0;
        for (const glm::vec4& v : after)
          for (int c = 0; c < 4; ++c) bad += std::isfinite(v[c]) ? 0 : 1;
        for (float v : rawOutput(*fx)) bad += std::isfinite(v) ? 0 : 1;
        if (bad != 0)
          fail(group, "Ok with NaN/Inf",
               where + ": Ok with " + std::to_string(bad) + " NaN/Inf values");
      } else {
        ++outcome.refused[postfx::toString(r)];
        if (message.empty())
          fail(group, "no message", where + ": " + postfx::toString(r) + " without a message");
        if (std::memcmp(after.data(), std::vector<glm::vec4>(after.size(), kMarker).data(),
                        after.size() * sizeof(glm::vec4)) != 0)
          fail(group, "refused but drew",
               where + ": refused (" + message + ") but the target changed");
      }
      const GlSnapshot afterState = snapshotGlState();
      std::string changed;
      for (const auto& [name, value] : before)
        if (value != afterState.at(name)) changed += name + " ";
      if (!changed.empty())
        fail(group, "GL state changed", where + ": GL state changed: " + changed);
      const std::string glErrors = takeGlErrors();
      if (!glErrors.empty()) fail(group, "GL error", where + ": GL errors: " + glErrors);
      for (const Pristine* p : spoiled)
        if (p != nullptr) p->restore();

      // The next ordinary frame: as in a fresh context, to the bit.
      const std::vector<glm::vec4> next = run(*fx, ordinary, r);
      if (r != Result::Ok) {
        fail(group, "next frame refused",
             where + ": the ordinary frame after it failed: " + postfx::lastError(fx.get()));
      } else if (std::memcmp(next.data(), reference.data(), next.size() * sizeof(glm::vec4)) != 0 ||
                 rawOutput(*fx) != rawReference) {
        fail(group, "next frame differs",
             where + ": the next ordinary frame differs from a fresh context's (" +
                 postfx::toString(Result::Ok) + " case: " + message + ")");
        // A poisoned context would fail every later case: count this one, go on afresh.
        ASSERT_EQ(postfx::create(desc, raw), Result::Ok) << postfx::lastError(nullptr);
        fx.reset(raw);
      }
      if (failures > 200) break;  // broken beyond telling: the report above says how
    }
    glDeleteTextures(1, &shadow);
    glDeleteTextures(1, &water);
  }

  int total = 0, ok = 0;
  std::printf("%-18s %6s %6s  refused by result\n", "field group", "cases", "Ok");
  for (int g = 0; g < kGroupCount; ++g) {
    std::string refused;
    for (const auto& [name, count] : outcomes[g].refused)
      refused += name + " " + std::to_string(count) + "  ";
    std::string broken;
    for (const auto& [name, count] : outcomes[g].broken)
      broken += name + " " + std::to_string(count) + "  ";
    std::printf("%-18s %6d %6d  %s%s%s\n", kGroupNames[g], outcomes[g].cases, outcomes[g].ok,
                refused.c_str(), broken.empty() ? "" : "| BROKEN: ", broken.c_str());
    total += outcomes[g].cases;
    ok += outcomes[g].ok;
  }
  std::printf("fuzz: %d cases in %zu contexts (seed 0x%llx), %d Ok, %d refused, %d failures\n",
              total, std::size(specs), static_cast<unsigned long long>(kSeed), ok, total - ok,
              failures);
  EXPECT_EQ(failures, 0);
  // Both outcomes occur in every group but the texel ones (which only corrupt data).
  for (int g = 0; g < kGroupCount; ++g) {
    EXPECT_GT(outcomes[g].ok, 0) << kGroupNames[g];
    if (g != kGBufferTexels && g != kWaterTexels) {
      EXPECT_LT(outcomes[g].ok, outcomes[g].cases) << kGroupNames[g] << ": nothing refused";
    }
  }
}

}  // namespace
