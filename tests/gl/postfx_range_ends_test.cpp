// Every documented range at its exact ends, and every enum out of its values. A random fuzz
// never lands on a bound (ObjectCausticsSettings::gridSize = 2048, the documented maximum, once
// returned Ok, drew nothing and left GL_INVALID_VALUE in the host's queue: 65,536 work groups,
// one past GL's guaranteed 65,535). So each knob is set to its minimum and its maximum, exactly:
// the frame is drawn (or refused by a budget, with a message naming it) with no GL error and
// finite light. Just past either end it is refused, the message naming the field and the value.
#include <gtest/gtest.h>
#include <postfx/local_water.h>
#include <postfx/reflected_caustics.h>
#include <postfx/testing.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "gl_fixture.h"
#include "postfx_object_caustics_util.h"
#include "postfx_scene.h"
#include "postfx_test_util.h"

namespace {

using namespace postfxtest;
using postfx::Feature;
using postfx::Result;

// One numeric field: how to set it, its documented range, and whether it is an int (the values
// just outside are then +-1) or a float (the next float outward).
struct Knob {
  const char* field;
  std::function<void(postfx::FrameDesc&, double)> set;
  double lo, hi;
  bool integer = false;
};

// One enum field: how to set it from an integer, and the integers that are its values.
struct EnumKnob {
  const char* field;
  std::function<void(postfx::FrameDesc&, long long)> set;
  std::vector<long long> values;
};

double below(const Knob& k) {
  return k.integer ? k.lo - 1.0 : double(std::nextafter(float(k.lo), -FLT_MAX));
}
double above(const Knob& k) {
  return k.integer ? k.hi + 1.0 : double(std::nextafter(float(k.hi), FLT_MAX));
}

// A frame with every feature's knobs reachable: seabed caustics, god rays, local water, reflected
// caustics on the seabed scene; object and volume caustics on the object host.
struct Target {
  const char* name;
  postfx::Context* fx;
  const Scene* scene;
  postfx::FrameDesc frame;
};

bool finiteTarget(const Scene& scene) {
  for (const glm::vec4& p : readRgba(scene.target, scene.spec().width, scene.spec().height))
    if (!std::isfinite(p.r) || !std::isfinite(p.g) || !std::isfinite(p.b)) return false;
  return true;
}

// A value inside the range: drawn with no GL error and finite light, or refused by a budget
// (memory, work) whose message says so. Never refused as out of range.
void expectDrawn(const Target& s, const postfx::FrameDesc& frame, const std::string& what) {
  SCOPED_TRACE(what);
  s.scene->clearTarget(glm::vec4(0.0f));
  const Result r = postfx::dispatch(*s.fx, frame);
  const std::string message = r == Result::Ok ? "" : postfx::lastError(s.fx);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR)) << "a GL error left in the host's queue";
  if (r == Result::Ok) {
    EXPECT_TRUE(finiteTarget(*s.scene)) << "non-finite light";
  } else {
    EXPECT_TRUE(message.find("budget") != std::string::npos)
        << "a value in its range refused: " << postfx::toString(r) << ": " << message;
  }
}

void expectRefused(const Target& s, const postfx::FrameDesc& frame, const std::string& field,
                   const std::string& what) {
  SCOPED_TRACE(what);
  const Result r = postfx::dispatch(*s.fx, frame);
  EXPECT_EQ(r, Result::InvalidArgument);
  const std::string message = postfx::lastError(s.fx);
  EXPECT_NE(message.find(field), std::string::npos) << "message names no field: " << message;
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

class PostfxRangeEndsTest : public testsupport::GlTest {};

TEST_F(PostfxRangeEndsTest, EveryRangeEndIsDrawnAndEveryValuePastItRefused) {
  SceneSpec spec;
  spec.width = 64;
  spec.height = 48;
  Scene seabed(spec);
  const GLuint water = makeWaterTexture(32, 3, 0.02);
  const FlatRegion flat = makeFlatRegion(8);
  const postfx::LocalWater& region = flat.region;

  auto water_ = makeContext(Feature::Caustics | Feature::GodRays | Feature::WavefrontAreaRatio |
                            Feature::LocalWater | Feature::ReflectedCaustics | Feature::Dispersion);
  postfx::FrameDesc waterFrame = makeFrame(seabed, water, 3);
  waterFrame.water.localWater = &region;
  waterFrame.water.localWaterCount = 1;
  ObjectHost host(sunAt(20.0, 30.0));
  const GlMesh mesh = makeSphereMesh(1.0, 16, 8);
  const postfx::CasterMesh caster =
      mesh.caster(translation({0.2, 1.5, 0.1}), postfx::CasterMaterial{});
  auto objects = makeObjectContext(Feature::VolumeCaustics);
  postfx::ObjectCausticsSettings settings;
  settings.gridSize = 32;
  settings.mapSize = 64;
  postfx::FrameDesc objectFrame = host.frame(&caster, 1, settings);
  objectFrame.water.level = 10.0;  // the volume's rays are under water

  const Target seabedSetup{"seabed", water_.get(), &seabed, waterFrame};
  const Target objectSetup{"objects", objects.get(), &host.scene, objectFrame};

  using F = postfx::FrameDesc;
  const std::vector<std::pair<const Target*, Knob>> knobs = {
      // CausticsSettings (settings.h)
      {&seabedSetup,
       {"caustics.tau", [](F& f, double v) { f.caustics.tau = float(v); }, postfx::kTauRange.min,
        postfx::kTauRange.max}},
      {&seabedSetup,
       {"caustics.reflectionWeight", [](F& f, double v) { f.caustics.reflectionWeight = float(v); },
        0.0, 1.0}},
      {&seabedSetup,
       {"caustics.intensity", [](F& f, double v) { f.caustics.intensity = float(v); },
        postfx::kIntensityRange.min, postfx::kIntensityRange.max}},
      {&seabedSetup,
       {"caustics.surfaceFadeDepth", [](F& f, double v) { f.caustics.surfaceFadeDepth = float(v); },
        postfx::kFadeDepthRange.min, postfx::kFadeDepthRange.max}},
      {&seabedSetup,
       {"caustics.triplanarSharpness",
        [](F& f, double v) { f.caustics.triplanarSharpness = float(v); },
        postfx::kTriplanarSharpnessRange.min, postfx::kTriplanarSharpnessRange.max}},
      {&seabedSetup,
       {"caustics.lodBias", [](F& f, double v) { f.caustics.lodBias = float(v); },
        postfx::kLodBiasRange.min, postfx::kLodBiasRange.max}},
      {&seabedSetup,
       {"caustics.minCascadeContrast",
        [](F& f, double v) { f.caustics.minCascadeContrast = float(v); }, 0.0, 1.0}},
      {&seabedSetup,
       {"caustics.tileResolution", [](F& f, double v) { f.caustics.tileResolution = int(v); },
        double(postfx::kTileResolutionRange.min), double(postfx::kTileResolutionRange.max), true}},
      {&seabedSetup,
       {"caustics.tileDepthLayers", [](F& f, double v) { f.caustics.tileDepthLayers = int(v); },
        4.0, 8.0, true}},  // 4 or 8: the values past them are 3 and 9
      {&seabedSetup,
       {"caustics.tileMinModulation",
        [](F& f, double v) { f.caustics.tileMinModulation = float(v); },
        postfx::kTileMinModulationRange.min, postfx::kTileMinModulationRange.max}},
      {&seabedSetup,
       {"caustics.gridResolution",
        [](F& f, double v) {
          f.caustics.model = postfx::CausticsModel::WavefrontAreaRatio;
          f.caustics.gridResolution = int(v);
        },
        double(postfx::kGridResolutionRange.min), double(postfx::kGridResolutionRange.max), true}},
      {&seabedSetup,
       {"caustics.windowSize",
        [](F& f, double v) {
          f.caustics.model = postfx::CausticsModel::WavefrontAreaRatio;
          f.caustics.windowSize = float(v);
        },
        postfx::kWindowSizeRange.min, postfx::kWindowSizeRange.max}},
      {&seabedSetup,
       {"caustics.depthLayers",
        [](F& f, double v) {
          f.caustics.model = postfx::CausticsModel::WavefrontAreaRatio;
          f.caustics.depthLayers = int(v);
        },
        double(postfx::kDepthLayersRange.min), double(postfx::kDepthLayersRange.max), true}},
      {&seabedSetup,
       {"caustics.maxReceiverDepth", [](F& f, double v) { f.caustics.maxReceiverDepth = float(v); },
        postfx::kMaxReceiverDepthRange.min, postfx::kMaxReceiverDepthRange.max}},
      {&seabedSetup,
       {"caustics.maxIrradiance", [](F& f, double v) { f.caustics.maxIrradiance = float(v); },
        postfx::kMaxIrradianceRange.min, postfx::kMaxIrradianceRange.max}},
      // GodRaySettings
      {&seabedSetup,
       {"godRays.sampleCount", [](F& f, double v) { f.godRays.sampleCount = int(v); },
        double(postfx::kGodRaySampleCountRange.min), double(postfx::kGodRaySampleCountRange.max),
        true}},
      {&seabedSetup,
       {"godRays.gridSpacing", [](F& f, double v) { f.godRays.gridSpacing = float(v); },
        postfx::kGridSpacingRange.min, postfx::kGridSpacingRange.max}},
      {&seabedSetup,
       {"godRays.intensity", [](F& f, double v) { f.godRays.intensity = float(v); },
        postfx::kIntensityRange.min, postfx::kIntensityRange.max}},
      {&seabedSetup,
       {"godRays.surfaceFadeDistance",
        [](F& f, double v) { f.godRays.surfaceFadeDistance = float(v); },
        postfx::kFadeDepthRange.min, postfx::kFadeDepthRange.max}},
      {&seabedSetup,
       {"godRays.depthFadeDistance", [](F& f, double v) { f.godRays.depthFadeDistance = float(v); },
        postfx::kDepthFadeDistanceRange.min, postfx::kDepthFadeDistanceRange.max}},
      {&seabedSetup,
       {"godRays.maxDistance", [](F& f, double v) { f.godRays.maxDistance = float(v); },
        postfx::kMaxMarchDistanceRange.min, postfx::kMaxMarchDistanceRange.max}},
      // WaterSurface, Sun (frame_desc.h)
      {&seabedSetup,
       {"sun.irradiance", [](F& f, double v) { f.sun.irradiance = glm::vec3(float(v)); },
        postfx::kIrradianceRange.min, postfx::kIrradianceRange.max}},
      {&seabedSetup,
       {"sun.angularDiameterDegrees",
        [](F& f, double v) { f.sun.angularDiameterDegrees = float(v); },
        postfx::kSunAngularDiameterRange.min, postfx::kSunAngularDiameterRange.max}},
      {&seabedSetup,
       {"water.longestWavelength[0]", [](F& f, double v) { f.water.longestWavelength[0] = v; },
        4.9e-324, postfx::kWaveStatisticRange.max}},
      {&seabedSetup,
       {"water.rmsLaplacian[1]", [](F& f, double v) { f.water.rmsLaplacian[1] = v; }, 4.9e-324,
        postfx::kWaveStatisticRange.max}},
      {&seabedSetup,
       {"water.ior", [](F& f, double v) { f.water.ior = float(v); }, postfx::kIorRange.min,
        postfx::kIorRange.max}},
      {&seabedSetup,
       {"water.absorption", [](F& f, double v) { f.water.absorption = glm::vec3(float(v)); },
        postfx::kWaterCoefficientRange.min, postfx::kWaterCoefficientRange.max}},
      {&seabedSetup,
       {"water.scattering", [](F& f, double v) { f.water.scattering = glm::vec3(float(v)); },
        postfx::kWaterCoefficientRange.min, postfx::kWaterCoefficientRange.max}},
      // LocalWater (local_water.h): the region is the frame's, so each knob edits a copy.
      // ReflectedCausticsSettings (reflected_caustics.h)
      {&seabedSetup,
       {"reflectedCaustics.intensity",
        [](F& f, double v) { f.reflectedCaustics.intensity = float(v); },
        postfx::kIntensityRange.min, postfx::kIntensityRange.max}},
      {&seabedSetup,
       {"reflectedCaustics.windowSize",
        [](F& f, double v) { f.reflectedCaustics.windowSize = float(v); },
        postfx::kWindowSizeRange.min, postfx::kWindowSizeRange.max}},
      {&seabedSetup,
       {"reflectedCaustics.gridResolution",
        [](F& f, double v) { f.reflectedCaustics.gridResolution = int(v); },
        double(postfx::kReflectedGridRange.min), double(postfx::kReflectedGridRange.max), true}},
      {&seabedSetup,
       {"reflectedCaustics.heightLayers",
        [](F& f, double v) {
          f.reflectedCaustics.landing = postfx::ReflectedLanding::HeightLayers;
          f.reflectedCaustics.heightLayers = int(v);
        },
        double(postfx::kReflectedLayersRange.min), double(postfx::kReflectedLayersRange.max),
        true}},
      {&seabedSetup,
       {"reflectedCaustics.maxHeight",
        [](F& f, double v) { f.reflectedCaustics.maxHeight = float(v); },
        postfx::kReflectedHeightRange.min, postfx::kReflectedHeightRange.max}},
      {&seabedSetup,
       {"reflectedCaustics.maxIrradiance",
        [](F& f, double v) { f.reflectedCaustics.maxIrradiance = float(v); },
        postfx::kMaxIrradianceRange.min, postfx::kMaxIrradianceRange.max}},
      // ObjectCausticsSettings (casters.h)
      {&objectSetup,
       {"objectCaustics.settings.gridSize",
        [](F& f, double v) { f.objectCaustics.settings.gridSize = int(v); }, 16.0, 2048.0, true}},
      {&objectSetup,
       {"objectCaustics.settings.iterations",
        [](F& f, double v) { f.objectCaustics.settings.iterations = int(v); }, 1.0, 8.0, true}},
      {&objectSetup,
       {"objectCaustics.settings.exitIterations",
        [](F& f, double v) { f.objectCaustics.settings.exitIterations = int(v); }, 1.0, 8.0, true}},
      {&objectSetup,
       {"objectCaustics.settings.splatRadius",
        [](F& f, double v) { f.objectCaustics.settings.splatRadius = float(v); }, 0.5, 8.0}},
      {&objectSetup,
       {"objectCaustics.settings.footprintScale",
        [](F& f, double v) { f.objectCaustics.settings.footprintScale = float(v); }, 1.0, 8.0}},
      {&objectSetup,
       {"objectCaustics.settings.intensity",
        [](F& f, double v) { f.objectCaustics.settings.intensity = float(v); }, 0.0, 1e4}},
      {&objectSetup,
       {"objectCaustics.settings.temporalWeight",
        [](F& f, double v) {
          f.objectCaustics.settings.temporalFilter = true;
          f.objectCaustics.settings.temporalWeight = float(v);
        },
        0.0, 0.95}},
  };

  int drawn = 0, refused = 0;
  for (const auto& [setup, knob] : knobs) {
    for (const double v : {knob.lo, knob.hi}) {
      postfx::FrameDesc f = setup->frame;
      knob.set(f, v);
      char what[160];
      std::snprintf(what, sizeof what, "%s = %.9g (an end of its range)", knob.field, v);
      expectDrawn(*setup, f, what);
      ++drawn;
    }
    for (const double v : {below(knob), above(knob)}) {
      postfx::FrameDesc f = setup->frame;
      knob.set(f, v);
      char what[160];
      std::snprintf(what, sizeof what, "%s = %.9g (just past its range)", knob.field, v);
      // The zero minimum of a wave statistic is "unknown"; below it is negative.
      expectRefused(*setup, f, knob.field, what);
      ++refused;
    }
  }

  // Local water's knobs, each on a copy of the region.
  struct RegionKnob {
    const char* field;
    std::function<void(postfx::LocalWater&, double)> set;
    Knob range;
  };
  using L = postfx::LocalWater;
  const std::vector<RegionKnob> regionKnobs = {
      {"gridResolution",
       [](L& r, double v) { r.gridResolution = int(v); },
       {"",
        {},
        double(postfx::kLocalWaterGridRange.min),
        double(postfx::kLocalWaterGridRange.max),
        true}},
      {"depthLayers",
       [](L& r, double v) { r.depthLayers = int(v); },
       {"",
        {},
        double(postfx::kLocalWaterLayerRange.min),
        double(postfx::kLocalWaterLayerRange.max),
        true}},
      {"maxDepth",
       [](L& r, double v) { r.maxDepth = float(v); },
       {"", {}, postfx::kLocalWaterDepthRange.min, postfx::kLocalWaterDepthRange.max}},
  };
  for (const RegionKnob& knob : regionKnobs) {
    const Knob& k = knob.range;
    for (int end = 0; end < 4; ++end) {
      postfx::LocalWater copy = region;
      postfx::FrameDesc f = waterFrame;
      f.water.localWater = &copy;
      const double v = end == 0 ? k.lo : end == 1 ? k.hi : end == 2 ? below(k) : above(k);
      knob.set(copy, v);
      char what[160];
      std::snprintf(what, sizeof what, "local water %s = %.9g", knob.field, v);
      if (end < 2) {
        expectDrawn(seabedSetup, f, what);
        ++drawn;
      } else {
        expectRefused(seabedSetup, f, knob.field, what);
        ++refused;
      }
    }
  }
  std::printf("%d range ends drawn (or refused by a budget), %d values past them refused\n", drawn,
              refused);
  glDeleteTextures(1, &flat.texture);
  glDeleteTextures(1, &water);
}

TEST_F(PostfxRangeEndsTest, EveryEnumOutOfItsValuesIsRefusedWithItsValues) {
  SceneSpec spec;
  spec.width = 64;
  spec.height = 48;
  Scene seabed(spec);
  const GLuint water = makeWaterTexture(32, 3, 0.02);
  auto fx = makeContext(Feature::Caustics | Feature::GodRays | Feature::WavefrontAreaRatio |
                        Feature::ReflectedCaustics);
  const postfx::FrameDesc base = makeFrame(seabed, water, 3);
  const Target setup{"seabed", fx.get(), &seabed, base};
  using F = postfx::FrameDesc;
  const std::vector<EnumKnob> enums = {
      {"caustics.model",
       [](F& f, long long v) { f.caustics.model = static_cast<postfx::CausticsModel>(v); },
       {0, 1, 2}},
      {"caustics.tileLookupResolution",
       [](F& f, long long v) {
         f.caustics.tileLookupResolution = static_cast<postfx::CausticsLookupResolution>(v);
       },
       {1, 2}},
      {"godRays.resolution",
       [](F& f, long long v) { f.godRays.resolution = static_cast<postfx::GodRayResolution>(v); },
       {1, 2, 4}},
      {"reflectedCaustics.landing",
       [](F& f, long long v) {
         f.reflectedCaustics.landing = static_cast<postfx::ReflectedLanding>(v);
       },
       {0, 1}},
      {"viewExtinction",
       [](F& f, long long v) {
         f.godRays.enabled = false;  // Host extinction refuses god rays
         f.viewExtinction = static_cast<postfx::ViewExtinction>(v);
       },
       {0, 1}},
  };
  int refused = 0;
  for (const EnumKnob& e : enums) {
    const long long last = e.values.back();
    for (const long long v : {-1LL, 3LL, last + 1, 7LL, 255LL}) {
      if (std::find(e.values.begin(), e.values.end(), v) != e.values.end()) continue;
      postfx::FrameDesc f = base;
      e.set(f, v);
      const std::string what = std::string(e.field) + " = " + std::to_string(v);
      SCOPED_TRACE(what);
      // Only the enums whose storage holds -1 get it; an unsigned underlying type wraps.
      const Result r = postfx::dispatch(*fx, f);
      EXPECT_EQ(r, Result::InvalidArgument);
      const std::string message = postfx::lastError(fx.get());
      EXPECT_NE(message.find(e.field), std::string::npos) << message;
      EXPECT_NE(message.find(" is not a "), std::string::npos) << message;
      EXPECT_NE(message.find('('), std::string::npos) << "names no accepted value: " << message;
      EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
      ++refused;
    }
    for (const long long v : e.values) {
      postfx::FrameDesc f = base;
      e.set(f, v);
      expectDrawn(setup, f, std::string(e.field) + " = " + std::to_string(v));
    }
  }
  std::printf("%d enum values out of range refused\n", refused);
  glDeleteTextures(1, &water);
}

}  // namespace
