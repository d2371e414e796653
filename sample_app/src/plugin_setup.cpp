#include "plugin_setup.h"
#include <postfx/testing.h>

#include "caster_admission.h"
#include "sun_light.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

namespace ocean {

namespace {

// Lambert's 1/pi: the plugin's caustic light is irradiance times albedo (docs/integration.md).
constexpr float kLambertian = 0.318309886f;
// An isotropic phase function, 1 / (4 pi) per steradian.
constexpr float kIsotropicPhase = 0.0795774715f;

// The ocean's cascades the plugin is given: the context is created for exactly these.
int pluginCascades(const postfx::water::Ocean& ocean) {
  return std::min(ocean.cascadeCount(), postfx::kMaxCascades);
}

// True when the caster's world box, projected by a light map's matrix, overlaps the map's
// square: a caster beyond every map lights no receiver this frame. Left out, it neither costs the
// plugin a caster nor widens the sun's caster map, whose fit spans all the casters it is given (the
// shallow reef's pair, 60 m from the deep presets, would blur their caustics 5x).
bool insideLightMap(const CasterInstance& c, const glm::dmat4& worldToClip) {
  glm::dvec2 lo(std::numeric_limits<double>::max()), hi(-lo);
  for (int i = 0; i < 8; ++i) {
    const glm::dvec3 p((i & 1) ? c.boundsMax.x : c.boundsMin.x,
                       (i & 2) ? c.boundsMax.y : c.boundsMin.y,
                       (i & 4) ? c.boundsMax.z : c.boundsMin.z);
    const glm::dvec4 clip = worldToClip * (c.transform * glm::dvec4(p, 1.0));
    if (!(clip.w > 0.0)) return true;  // behind a local light's eye: let the plugin decide
    const glm::dvec2 ndc = glm::dvec2(clip) / clip.w;
    lo = glm::min(lo, ndc);
    hi = glm::max(hi, ndc);
  }
  return hi.x >= -1.0 && lo.x <= 1.0 && hi.y >= -1.0 && lo.y <= 1.0;
}

bool lightsAReceiver(const CasterInstance& c, const HostFrame& frame) {
  if (insideLightMap(c, frame.shadowWorldToClip)) return true;
  for (const HostLight& light : frame.lights) {
    if (light.receiverMap != 0 && insideLightMap(c, light.worldToClip)) return true;
  }
  return false;
}

}  // namespace

float PluginSetup::reflectedIntensity(const HostFrame& frame) const {
  // Sun::irradiance is the beam below the surface, (1 - F) of the sun above it (sun_light.h);
  // the sea mirrors the sun above. With the sun at or below the horizon there is neither.
  const float transmission = sunTransmission(frame.input.sun, frame.optics.ior);
  if (!(transmission > 0.0f)) return 0.0f;
  // Within the plugin's range at a grazing sun, where 1 - F tends to 0 (so does the light).
  return std::min(reflectedCaustics_.intensity / transmission, postfx::kIntensityRange.max);
}

std::unique_ptr<PluginSetup> PluginSetup::create(Renderer& renderer, const Options& options,
                                                 bool benchmarkFloor, std::string& error) {
  std::unique_ptr<PluginSetup> setup(new PluginSetup());
  postfx::CreateDesc desc;
  desc.features = postfx::Feature::Caustics | postfx::Feature::ShadowMask |
                  postfx::Feature::Dispersion | postfx::Feature::GodRays;
  if (benchmarkFloor) desc.features = desc.features | postfx::testing::BenchmarkFloor;
  // The physical model's GL resources exist only when it is asked for.
  if (options.physicalCaustics) desc.features = desc.features | postfx::Feature::WavefrontAreaRatio;
  if (options.objectCaustics) {
    desc.features = desc.features | postfx::Feature::ObjectCaustics;
    if (options.volumeCaustics) desc.features = desc.features | postfx::Feature::VolumeCaustics;
    renderer.enableReceiverMap();
    // Exactly the scene's lights: the bound is a shader constant, 0 compiles no light code.
    desc.maxLocalLights = int(renderer.lights().size());
  }
  desc.depthConvention = postfx::DepthConvention::ReverseZ;
  desc.normalEncoding = postfx::NormalEncoding::Octahedral;
  desc.maxWaterCascades = pluginCascades(renderer.ocean());
  if (options.triplanarWalls) desc.features = desc.features | postfx::Feature::TriplanarWalls;
  // Only a scene with local water (the pool, a wake) asks for it: off, no shader reads it.
  if (renderer.localWater() != nullptr) desc.features = desc.features | postfx::Feature::LocalWater;
  // Reflected caustics only where the run wants them (the harbour preset, --reflected-caustics):
  // off, none of their passes or resources exist.
  const bool reflected = options.reflectedCaustics.value_or(false);
  if (reflected) desc.features = desc.features | postfx::Feature::ReflectedCaustics;
  desc.workAccount = options.workAccount != Options::WorkAccount::Off;
  if (options.workAccount == Options::WorkAccount::Counted)
    desc.features = desc.features | postfx::testing::CountShaderWork;
  if (options.workAccount == Options::WorkAccount::Timed)
    desc.features = desc.features | postfx::testing::TimeEachStep;
  if (postfx::create(desc, setup->context_) != postfx::Result::Ok) {
    error = std::string("postfx: ") + postfx::lastError(nullptr);
    return nullptr;
  }
  setup->createDesc_ = desc;
  setup->flatLocalWater_ = options.flatLocalWater;
  setup->localWaterGrid_ = options.localWaterGrid;
  if (options.flatLocalWater) {
    glCreateTextures(GL_TEXTURE_2D, 1, &setup->flatSurface_);
    glTextureStorage2D(setup->flatSurface_, 1, GL_RG32F, 1, 1);
    const float zero[2] = {0.0f, 0.0f};
    glTextureSubImage2D(setup->flatSurface_, 0, 0, 0, 1, 1, GL_RG, GL_FLOAT, zero);
  }
  setup->flatWater_ = options.flatWater;
  if (options.flatWater) {
    // One zero texel per cascade: zero slopes and height, wrapped over every tile (a texture
    // without B and A reads height 0 and Jacobian 1, flat water's).
    const int layers = desc.maxWaterCascades;
    glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &setup->flatWaterTexture_);
    glTextureStorage3D(setup->flatWaterTexture_, 1, GL_RG32F, 1, 1, layers);
    const std::vector<float> zero(size_t(2 * layers), 0.0f);
    glTextureSubImage3D(setup->flatWaterTexture_, 0, 0, 0, 0, 1, 1, layers, GL_RG, GL_FLOAT,
                        zero.data());
  }
  setup->caustics_.enabled = options.caustics;
  // The plugin's caustics are the sample's underwater sun (lighting.frag lights none below the
  // level): given the beam below the surface (dispatch), 1/pi makes its caustic copy the
  // Lambertian direct light, and no surface fade, since a fade would darken the sun itself
  // near the surface, not only its pattern (which tends to flat water's there anyway).
  setup->caustics_.intensity = kLambertian;
  setup->caustics_.surfaceFadeDepth = 0.0f;
  // The light through and off the casters is the same sun's (and the lights'), in the same
  // units: their shadows in the host's map remove what they block, this adds back what passes.
  setup->objectCaustics_.intensity = kLambertian;
  // The light they focus in the water scatters like the god rays' sun (their phase and fades):
  // it fills the shadow the casters cut into the shafts.
  if (options.volumeMethod > 0)
    setup->objectCaustics_.volume.method = options.volumeMethod == 1
                                               ? postfx::VolumeCausticsMethod::Beams
                                               : postfx::VolumeCausticsMethod::Lines;
  setup->godRays_.enabled = options.godRays;
  // The sun's single scattering with an isotropic phase function, 1 / (4 pi) per steradian,
  // as the sample's fog scatters the sky's light (sample_optics.h): the shafts in the same
  // units as the seabed's light.
  setup->godRays_.intensity = kIsotropicPhase;
  if (options.tau >= 0.0) setup->caustics_.tau = float(options.tau);
  if (options.tileResolution > 0) setup->caustics_.tileResolution = options.tileResolution;
  if (options.maxReceiverDepth > 0.0)
    setup->caustics_.maxReceiverDepth = float(options.maxReceiverDepth);
  if (options.tileDepthLayers > 0) setup->caustics_.tileDepthLayers = options.tileDepthLayers;
  if (options.causticsLookup > 0)
    setup->caustics_.tileLookupResolution =
        static_cast<postfx::CausticsLookupResolution>(options.causticsLookup);
  if (options.godRayResolution > 0)
    setup->godRays_.resolution = static_cast<postfx::GodRayResolution>(options.godRayResolution);
  if (options.godRaySamples > 0) setup->godRays_.sampleCount = options.godRaySamples;
  if (options.physicalCaustics) {
    setup->caustics_.model = postfx::CausticsModel::WavefrontAreaRatio;
    setup->caustics_.gridResolution = options.causticsGrid;
    setup->caustics_.windowSize = float(options.causticsWindow);
    setup->caustics_.depthLayers = options.causticsLayers;
  }
  if (options.rayDeviationCaustics) setup->caustics_.model = postfx::CausticsModel::RayDeviation;
  // The reflected light as the Lambertian light of the sun the sea mirrors, like the caustics
  // (1/pi; describe() turns the plugin's sun, the beam below the surface, back into the sun
  // above it). The whole mirror light, its flat-water mean too: the sample lights nothing with
  // light the sea reflects (lighting.frag: the sun, the lights and the sky), so nothing counts
  // it twice.
  setup->reflectedCaustics_.enabled = reflected;
  setup->reflectedCaustics_.intensity = kLambertian;
  setup->reflectedCaustics_.includeMirrorMean = true;
  if (options.reflectedGrid > 0) setup->reflectedCaustics_.gridResolution = options.reflectedGrid;
  if (options.reflectedLanding > 0)
    setup->reflectedCaustics_.landing = options.reflectedLanding == 1
                                            ? postfx::ReflectedLanding::ViewDepth
                                            : postfx::ReflectedLanding::HeightLayers;
  if (options.reflectedMaxHeight > 0.0)
    setup->reflectedCaustics_.maxHeight = float(options.reflectedMaxHeight);
  PluginSetup* self = setup.get();
  renderer.setPluginPass([self](const HostFrame& frame, std::string& message) {
    return self->dispatch(frame, message);
  });
  return setup;
}

PluginSetup::~PluginSetup() {
  for (postfx::View* view : views_) postfx::destroyView(*context_, view);
  postfx::destroy(context_);
  if (flatSurface_ != 0) glDeleteTextures(1, &flatSurface_);
  if (flatWaterTexture_ != 0) glDeleteTextures(1, &flatWaterTexture_);
}

bool PluginSetup::dispatch(const HostFrame& frame, std::string& error) {
  const postfx::FrameDesc desc = describe(frame);
  lastFrame_ = desc;
  // bench --work: the dispatch's own time by the CPU's clock, from a drained pipeline to a
  // drained one (on a CPU rasteriser, the time it took).
  if (wallTimes_ != nullptr) glFinish();
  const auto start = std::chrono::steady_clock::now();
  const postfx::Result r = postfx::dispatch(*context_, desc);
  if (wallTimes_ != nullptr) {
    glFinish();
    wallTimes_->push_back(
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
            .count());
  }
  if (r != postfx::Result::Ok) {
    error = std::string("postfx: ") + postfx::lastError(context_);
    return false;
  }
  return true;
}

bool PluginSetup::dispatchViews(const std::vector<HostFrame>& frames, std::string& error) {
  if (frames.empty()) return true;
  while (views_.size() < frames.size()) {
    postfx::View* view = nullptr;
    if (postfx::createView(*context_, view) != postfx::Result::Ok) {
      error = std::string("postfx: ") + postfx::lastError(context_);
      return false;
    }
    views_.push_back(view);
  }
  std::vector<postfx::ViewDesc> views(frames.size());
  std::vector<postfx::SunShadowMap> shadows(frames.size());
  for (size_t i = 0; i < frames.size(); ++i) {
    // Each view's own G-buffer, camera and shadow cascade (fitted around its camera).
    const postfx::FrameDesc own = describe(frames[i]);
    postfx::ViewDesc& v = views[i];
    v.view = views_[i];
    v.depth = own.depth;
    v.normal = own.normal;
    v.albedo = own.albedo;
    v.target = own.target;
    v.camera = own.camera;
    shadows[i] = own.shadow;
    v.shadow = &shadows[i];
  }
  // Last: describe() rebuilds the casters and lights arrays the shared frame points into.
  const postfx::FrameDesc desc = describe(frames[0]);
  lastFrame_ = desc;
  if (postfx::dispatch(*context_, desc, views.data(), int(views.size())) != postfx::Result::Ok) {
    error = std::string("postfx: ") + postfx::lastError(context_);
    return false;
  }
  return true;
}

postfx::FrameDesc PluginSetup::describe(const HostFrame& frame) {
  const gbuffer::Targets& targets = frame.targets;
  const postfx::water::Ocean& ocean = frame.ocean;
  postfx::FrameDesc desc;
  desc.depth = {targets.depth(), GL_DEPTH_COMPONENT32F};
  desc.normal = {targets.normal(), GL_RG16_SNORM};
  desc.albedo = {targets.albedo(), GL_SRGB8_ALPHA8};
  desc.target = {frame.target, GL_RGBA16F};
  desc.camera.position = frame.input.camera.position;
  desc.camera.view = frame.input.camera.viewRotation();
  desc.camera.projection = glm::mat4(frame.projection);
  desc.sun.direction = frame.input.sun.direction();
  // The beam below the surface (atmosphere and 1 - Fresnel), not the sun above the air: the
  // plugin's light then equals the sample's own sun, which it replaces under the water.
  desc.sun.irradiance = sunIrradianceBelowSurface(frame.input.sun, frame.optics.ior);
  desc.water.level = frame.optics.level;
  desc.water.texture = {ocean.slopeTexture(), GL_RGBA16F};
  desc.water.cascadeCount = pluginCascades(ocean);
  for (int c = 0; c < desc.water.cascadeCount; ++c) {
    desc.water.tileSize[c] = ocean.tileSize(c);
    desc.water.rmsLaplacian[c] = ocean.waveStats(c).rmsLaplacian;
    desc.water.longestWavelength[c] = ocean.waveStats(c).longestWavelength;
  }
  if (flatWater_) {
    // --flat-water: a sea without waves. Its statistics are unknown (0), not the ocean's, so
    // that no cascade is left out for waves it does not have.
    desc.water.texture = {flatWaterTexture_, GL_RG32F};
    for (int c = 0; c < desc.water.cascadeCount; ++c) {
      desc.water.rmsLaplacian[c] = 0.0;
      desc.water.longestWavelength[c] = 0.0;
    }
  }
  desc.water.ior = float(frame.optics.ior);
  const float spread = float(frame.optics.iorSpread);
  desc.water.iorRgb =
      glm::vec3(desc.water.ior - 0.5f * spread, desc.water.ior, desc.water.ior + 0.5f * spread);
  desc.water.absorption =
      glm::vec3(frame.optics.absorption.r, frame.optics.absorption.g, frame.optics.absorption.b);
  // The same scattering the sample's fog uses: the god rays' extinction matches it.
  desc.water.scattering =
      glm::vec3(frame.optics.scattering.r, frame.optics.scattering.g, frame.optics.scattering.b);
  // The pool's (or a wake's) water: the host's own simulation texture, read during the dispatch.
  desc.water.localWater = frame.localWater.empty() ? nullptr : frame.localWater.data();
  desc.water.localWaterCount = int(frame.localWater.size());
  if ((flatLocalWater_ || localWaterGrid_ > 0) && !frame.localWater.empty()) {
    regions_ = frame.localWater;
    for (postfx::LocalWater& region : regions_) {
      if (flatLocalWater_) region.texture = {flatSurface_, GL_RG32F};
      if (localWaterGrid_ > 0) region.gridResolution = localWaterGrid_;
    }
    desc.water.localWater = regions_.data();
  }
  desc.shadow.depth = {frame.shadowMap, GL_DEPTH_COMPONENT32F};
  desc.shadow.worldToLightClip = frame.shadowWorldToClip;
  desc.shadow.depthConvention = postfx::DepthConvention::ForwardZeroToOne;
  desc.caustics = caustics_;
  desc.godRays = godRays_;
  desc.reflectedCaustics = reflectedCaustics_;
  desc.reflectedCaustics.intensity = reflectedIntensity(frame);
  // Object caustics: the host's own buffers, and the shadow map drawn without the casters as
  // the receivers. The casters stay in the host's shadow map, which removes the light they
  // block; the plugin adds back what passes through or reflects off them.
  casters_.clear();
  for (const CasterInstance& c : frame.casters) {
    // buildScene's admitCasters already kept the casters within budget (with a warning).
    if (int(casters_.size()) == postfx::kMaxCasters) break;
    if (!lightsAReceiver(c, frame)) continue;
    postfx::CasterMesh mesh;
    mesh.vertexBuffer = c.vertices;
    mesh.indexBuffer = c.indices;
    mesh.indexType = postfx::IndexType::UnsignedInt;
    mesh.vertexCount = c.vertexCount;
    mesh.indexCount = c.indexCount;
    mesh.positionOffset = 0;
    mesh.normalOffset = 12;
    mesh.stride = 24;
    mesh.boundsMin = c.boundsMin;
    mesh.boundsMax = c.boundsMax;
    mesh.modelToWorld = c.transform;
    mesh.material = casterMaterial(c.material);
    casters_.push_back(mesh);
  }
  desc.objectCaustics.casters = casters_.data();
  desc.objectCaustics.casterCount = frame.receiverMap != 0 ? int(casters_.size()) : 0;
  desc.objectCaustics.receivers.depth = {frame.receiverMap, GL_DEPTH_COMPONENT32F};
  desc.objectCaustics.receivers.worldToLightClip = frame.shadowWorldToClip;
  desc.objectCaustics.receivers.depthConvention = postfx::DepthConvention::ForwardZeroToOne;
  desc.objectCaustics.receivers.bias = 0.2f;  // m along the light (was 0.0005 of a 400 m range)
  desc.objectCaustics.settings = objectCaustics_;
  // Point and spot lights: each with its receiver map, drawn from the light like the sun's.
  lights_.clear();
  for (const HostLight& host : frame.lights) {
    if (host.receiverMap == 0) break;  // no object caustics
    const SceneLight& l = host.light;
    postfx::LocalLight light;
    light.type = l.type == SceneLight::Type::Spot ? postfx::LocalLightType::Spot
                                                  : postfx::LocalLightType::Point;
    light.position = l.position;
    light.direction = l.direction;
    light.intensity = l.intensity;
    light.range = l.range;
    light.coneAngleDegrees = l.coneAngleDegrees;
    light.coneSoftness = l.coneSoftness;
    light.receivers.depth = {host.receiverMap, GL_DEPTH_COMPONENT32F};
    light.receivers.worldToLightClip = host.worldToClip;
    light.receivers.depthConvention = postfx::DepthConvention::ForwardZeroToOne;
    light.receivers.bias = 0.2f;  // m along the light, as the sun's receivers
    lights_.push_back(light);
  }
  desc.objectCaustics.lights = lights_.data();
  desc.objectCaustics.lightCount = int(lights_.size());
  return desc;
}

std::string PluginSetup::timingSummary() const {
  const postfx::FrameStats& frameStats = stats();
  std::string summary;
  for (int i = 0; i < postfx::kPassCount; ++i) {
    const postfx::PassStats& pass = frameStats.passes[i];
    if (!pass.present) continue;
    char line[96];
    std::snprintf(line, sizeof(line), "%s%s %.3f ms", summary.empty() ? "" : "  |  ",
                  postfx::toString(postfx::Pass(i)), pass.skipped ? 0.0 : pass.medianMs);
    summary += line;
  }
  return summary.empty() ? "no passes timed yet" : summary;
}

}  // namespace ocean
