#include "renderer.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>

#include <gbuffer/codec.h>
#include <glkit/texture.h>

#include "shared/sample_frame.h"
#include "shared/sample_lights.h"
#include "shared/sample_optics.h"
#include "sun_light.h"

namespace ocean_sample {
const glkit::ShaderLibrary& shaderLibrary();
}

namespace ocean {
namespace {

bool build(glkit::Program& program, const char* vertex, const char* fragment, const char* label,
           std::string& error) {
  program = glkit::buildProgram(ocean_sample::shaderLibrary(),
                                {{GL_VERTEX_SHADER, vertex}, {GL_FRAGMENT_SHADER, fragment}}, "",
                                label, error);
  return program.id() != 0;
}

void drawFullscreen(GLuint vao) {
  glBindVertexArray(vao);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
}

}  // namespace

std::unique_ptr<Renderer> Renderer::create(const RenderSettings& settings,
                                           const ocean_scene::Model& scene, std::string& error) {
  std::unique_ptr<Renderer> renderer(new Renderer());
  renderer->settings_ = settings;
  if (!renderer->initialise(scene, error)) return nullptr;
  return renderer;
}

std::unique_ptr<Renderer> Renderer::createView(const RenderSettings& settings,
                                               const ocean_scene::Model& scene, Renderer& primary,
                                               std::string& error) {
  std::unique_ptr<Renderer> renderer(new Renderer());
  renderer->settings_ = settings;
  renderer->ocean_ = primary.ocean_;
  renderer->updatesOcean_ = false;
  renderer->optics_ = primary.optics_;
  renderer->localWater_ = primary.localWater_;
  if (!renderer->initialise(scene, error)) return nullptr;
  // The same world: the primary's receiver maps and lights.
  if (primary.receiverMap_.texture() != 0) renderer->enableReceiverMap();
  std::vector<SceneLight> lights;
  for (const HostLight& light : primary.hostLights_) lights.push_back(light.light);
  renderer->setLights(lights);
  return renderer;
}

bool Renderer::initialise(const ocean_scene::Model& scene, std::string& error) {
  if (targets_.resize(settings_.width, settings_.height, error) != gbuffer::TargetError::None) {
    return false;
  }
  if (!ocean_) {
    postfx::water::OceanDesc oceanDesc;
    oceanDesc.resolution = settings_.waterResolution;
    oceanDesc.windSpeed = settings_.windSpeed;
    std::unique_ptr<postfx::water::Ocean> ocean;
    if (postfx::water::Ocean::create(oceanDesc, ocean, error) != postfx::water::Result::Ok)
      return false;
    ocean_ = std::move(ocean);
  }

  if (!build(geometry_, "sample/geometry.vert", "sample/geometry.frag", "sample.geometry", error) ||
      !build(shadow_, "sample/shadow.vert", "sample/depth_only.frag", "sample.shadow", error) ||
      !build(lightShadow_, "sample/light_shadow.vert", "sample/depth_only.frag",
             "sample.light_shadow", error) ||
      !build(lighting_, "sample/fullscreen.vert", "sample/lighting.frag", "sample.lighting",
             error) ||
      !build(composite_, "sample/fullscreen.vert", "sample/composite.frag", "sample.fog", error) ||
      !build(water_, "sample/water_surface.vert", "sample/water_surface.frag",
             "sample.water_surface", error) ||
      !build(tonemap_, "sample/fullscreen.vert", "sample/tonemap.frag", "sample.tonemap", error)) {
    return false;
  }
  scene_.upload(scene);
  shadowMap_.create(settings_.shadowMapSize);
  waterGrid_.create(160, 256, 0.02f, 4000.0f);

  frameUniforms_ = glkit::createBuffer(sizeof(shared::SampleFrame), nullptr, GL_DYNAMIC_STORAGE_BIT,
                                       "sample.frame_constants");
  lightUniforms_ = glkit::createBuffer(sizeof(shared::SampleLights), nullptr,
                                       GL_DYNAMIC_STORAGE_BIT, "sample.light_constants");
  emptyVao_ = glkit::createVertexArray({});

  fogged_ = glkit::createTexture2D(GL_RGBA16F, settings_.width, settings_.height, GL_NEAREST,
                                   "sample.fogged");
  sceneBelow_ = glkit::createTexture2D(GL_RGBA16F, settings_.width, settings_.height, GL_LINEAR,
                                       "sample.scene_below_water");
  foggedFbo_ = glkit::createFramebuffer({});
  glNamedFramebufferTexture(foggedFbo_.id(), GL_COLOR_ATTACHMENT0, fogged_.id(), 0);
  glNamedFramebufferTexture(foggedFbo_.id(), GL_DEPTH_ATTACHMENT, targets_.depth(), 0);
  output_ = glkit::createTexture2D(GL_RGBA8, settings_.width, settings_.height, GL_NEAREST,
                                   "sample.output");
  outputFbo_ = glkit::createFramebuffer({});
  glNamedFramebufferTexture(outputFbo_.id(), GL_COLOR_ATTACHMENT0, output_.id(), 0);
  if (!casterSurfaces_.create(scene_, settings_.width, settings_.height, error)) return false;
  std::vector<GLuint> framebuffers = {foggedFbo_.id(), outputFbo_.id()};
  if (casterSurfaces_.hasGlass()) {
    displayDepth_ = glkit::createTexture2D(GL_DEPTH_COMPONENT32F, settings_.width, settings_.height,
                                           GL_NEAREST, "sample.display_depth");
    displayFbo_ = glkit::createFramebuffer({});
    glNamedFramebufferTexture(displayFbo_.id(), GL_COLOR_ATTACHMENT0, fogged_.id(), 0);
    glNamedFramebufferTexture(displayFbo_.id(), GL_DEPTH_ATTACHMENT, displayDepth_.id(), 0);
    framebuffers.push_back(displayFbo_.id());
  }
  for (GLuint fbo : framebuffers) {
    if (glCheckNamedFramebufferStatus(fbo, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
      error = "sample framebuffer incomplete";
      return false;
    }
  }
  return true;
}

void Renderer::enableReceiverMap() {
  if (receiverMap_.texture() == 0) receiverMap_.create(settings_.shadowMapSize);
  for (size_t i = 0; i < lightMaps_.size(); ++i) {
    LightDepthMaps& maps = *lightMaps_[i];
    if (maps.receivers.texture() == 0) maps.receivers.create(settings_.lightMapSize);
    hostLights_[i].receiverMap = maps.receivers.texture();
  }
}

void Renderer::setLights(const std::vector<SceneLight>& lights) {
  lightMaps_.clear();
  hostLights_.clear();
  for (size_t i = 0; i < lights.size() && i < size_t(kMaxSceneLights); ++i) {
    auto maps = std::make_unique<LightDepthMaps>();
    maps->light = lights[i];
    maps->worldToClip = lightWorldToClip(lights[i], maps->fovY);
    maps->shadow.create(settings_.lightMapSize);
    if (receiverMap_.texture() != 0) maps->receivers.create(settings_.lightMapSize);
    hostLights_.push_back({maps->light, maps->worldToClip, maps->receivers.texture()});
    lightMaps_.push_back(std::move(maps));
  }
}

void Renderer::updateLightConstants(const glm::dvec3& eye) {
  shared::SampleLights block{};
  block.lightCount = glm::vec4(float(lightMaps_.size()), 0.0f, 0.0f, 0.0f);
  for (size_t i = 0; i < lightMaps_.size(); ++i) {
    const LightDepthMaps& maps = *lightMaps_[i];
    const SceneLight& light = maps.light;
    const bool spot = light.type == SceneLight::Type::Spot;
    block.lightViewProjection[i] = ShadowMap::relativeTo(maps.worldToClip, eye);
    block.lightPosition[i] = glm::vec4(glm::vec3(light.position - eye), spot ? 1.0f : 0.0f);
    block.lightAxis[i] = glm::vec4(glm::vec3(glm::normalize(light.direction)), 0.0f);
    block.lightIntensity[i] = glm::vec4(light.intensity, float(light.position.y - optics_.level));
    const double half = glm::radians(0.5 * double(light.coneAngleDegrees));
    const double texelPerMetre = 2.0 * std::tan(0.5 * maps.fovY) / maps.shadow.size();
    block.lightCone[i] = glm::vec4(float(half), float(half * (1.0 - double(light.coneSoftness))),
                                   float(texelPerMetre), 0.0f);
  }
  glNamedBufferSubData(lightUniforms_.id(), 0, sizeof(block), &block);
}

void Renderer::drawLightMaps(const glm::dvec3& eye) {
  if (lightMaps_.empty()) return;
  glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, -1, "sample.light_shadow");
  glUseProgram(lightShadow_.id());
  const GLint matrix = glGetUniformLocation(lightShadow_.id(), "lightViewProjection");
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(1.5f, 2.0f);
  for (const std::unique_ptr<LightDepthMaps>& maps : lightMaps_) {
    const glm::mat4 relative = ShadowMap::relativeTo(maps->worldToClip, eye);
    glUniformMatrix4fv(matrix, 1, GL_FALSE, glm::value_ptr(relative));
    glViewport(0, 0, maps->shadow.size(), maps->shadow.size());
    glBindFramebuffer(GL_FRAMEBUFFER, maps->shadow.framebuffer());
    glClear(GL_DEPTH_BUFFER_BIT);
    scene_.draw(lightShadow_.id(), eye);
    if (maps->receivers.texture() != 0) {
      glBindFramebuffer(GL_FRAMEBUFFER, maps->receivers.framebuffer());
      glClear(GL_DEPTH_BUFFER_BIT);
      scene_.draw(lightShadow_.id(), eye, GpuScene::DrawSet::NonCasters);
    }
  }
  glDisable(GL_POLYGON_OFFSET_FILL);
  glPopDebugGroup();
}

glm::dmat4 Renderer::updateFrameConstants(const FrameInput& input) {
  const Camera& camera = input.camera;
  const double aspect = double(settings_.width) / settings_.height;
  const glm::dmat4 projection = camera.projection(aspect);
  const glm::dvec3 toSun = input.sun.direction();
  const double ior = optics_.ior;

  // The beam under water: refracted through the mean surface.
  const glm::dvec3 travel = glm::refract(-toSun, glm::dvec3(0, 1, 0), 1.0 / ior);
  const glm::dvec3 toSunUnderwater = toSun.y > 0.0 ? -travel : glm::dvec3(0, 1, 0);
  shadowWorldToClip_ =
      shadowMap_.fit(camera.position, glm::vec3(toSunUnderwater), settings_.shadowRadius);

  shared::SampleFrame frame{};
  frame.viewProjection = glm::mat4(projection) * camera.viewRotation();
  frame.cameraToWorld = glm::mat4(camera.rotation());
  frame.shadowViewProjection = ShadowMap::relativeTo(shadowWorldToClip_, camera.position);
  const gbuffer::ProjectionParams params =
      gbuffer::projectionParams(projection, gbuffer::DepthConvention::ReverseZ);
  frame.projectionXY = params.xy;
  frame.projectionZ = glm::vec4(params.z, float(gbuffer::DepthConvention::ReverseZ), 0.0f);
  frame.cameraHeight = glm::vec4(float(camera.position.y - optics_.level), 0.0f, 0.0f, 0.0f);
  frame.sunDirection = glm::vec4(glm::vec3(toSun), toSun.y > 0.0 ? 1.0f : 0.0f);
  frame.sunIrradiance = glm::vec4(sunIrradianceAboveWater(input.sun), 0.0f);
  frame.refractedSun = glm::vec4(glm::vec3(toSunUnderwater), sunTransmission(input.sun, ior));
  const float skyLight = 0.25f + 0.6f * float(std::max(toSun.y, 0.0));
  frame.ambient = glm::vec4(glm::vec3(0.45f, 0.6f, 0.85f) * skyLight, 0.0f);
  frame.absorption = glm::vec4(optics_.absorption.r, optics_.absorption.g, optics_.absorption.b, 0);
  frame.scattering = glm::vec4(optics_.scattering.r, optics_.scattering.g, optics_.scattering.b, 0);
  // The bend: a point h above the level moves by h (L / L.y - S / S.y) across the beam, S the sun
  // in air and L under the water (shadow_space.glsl).
  glm::dvec2 bend(0.0);
  if (settings_.airShadows && toSun.y > 0.0) {
    const glm::dvec3 shift = toSunUnderwater / toSunUnderwater.y - toSun / toSun.y;
    bend = glm::dvec2(shift.x, shift.z);
  }
  frame.waterParams = glm::vec4(float(ior), float(2.0 * settings_.shadowRadius / shadowMap_.size()),
                                float(bend.x), float(bend.y));
  for (int c = 0; c < ocean_->cascadeCount() && c < 4; ++c) {
    const double tile = ocean_->tileSize(c);
    // The camera's place in each tile, reduced in double: float never sees 1e6 m.
    const glm::dvec2 inTile = glm::fract(glm::dvec2(camera.position.x, camera.position.z) / tile);
    frame.cascadeTile[c] = glm::vec4(float(tile), float(1.0 / tile), glm::vec2(inTile));
  }
  frame.cascadeInfo =
      glm::vec4(float(std::min(ocean_->cascadeCount(), 4)), settings_.exposure, 0.0f, 0.0f);
  glNamedBufferSubData(frameUniforms_.id(), 0, sizeof(frame), &frame);
  return projection;
}

bool Renderer::render(const FrameInput& input, std::string& error) {
  if (!beginFrame(input, error)) return false;
  if (plugin_) {
    // After the fog, as the plugin's header asks (ViewExtinction::Plugin): the light it adds
    // arrives attenuated along the view ray, and fog applied after it would do so twice.
    if (!plugin_(hostFrame(), error)) return false;
  }
  endFrame();
  return true;
}

HostFrame Renderer::hostFrame() const {
  return HostFrame{targets_,
                   fogged_.id(),
                   input_,
                   *ocean_,
                   optics_,
                   shadowMap_.texture(),
                   shadowWorldToClip_,
                   projection_,
                   receiverMap_.texture(),
                   scene_.casters(),
                   hostLights_,
                   localWater_ ? localWater_->regions() : noLocalWater_};
}

bool Renderer::beginFrame(const FrameInput& input, std::string& error) {
  if (updatesOcean_ && ocean_->update(input.timeSeconds, error) != postfx::water::Result::Ok)
    return false;
  if (localWater_) {
    // Before the shadow maps: the instances it moves (a ball) cast their shadow where they are.
    if (updatesOcean_ && !localWater_->update(input.timeSeconds, error)) return false;
    for (const InstanceMove& move : localWater_->moves())
      scene_.setTransform(move.instance, move.transform);
  }
  input_ = input;
  const glm::dmat4 projection = updateFrameConstants(input);
  projection_ = projection;
  const int width = settings_.width, height = settings_.height;
  const glm::dvec3 eye = input.camera.position;

  glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
  glBindBufferBase(GL_UNIFORM_BUFFER, 0, frameUniforms_.id());
  glDisable(GL_BLEND);
  glDisable(GL_CULL_FACE);
  glDepthMask(GL_TRUE);
  glEnable(GL_DEPTH_TEST);

  glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, -1, "sample.shadow");
  glBindFramebuffer(GL_FRAMEBUFFER, shadowMap_.framebuffer());
  glViewport(0, 0, shadowMap_.size(), shadowMap_.size());
  glClearDepth(1.0);
  glClear(GL_DEPTH_BUFFER_BIT);
  glDepthFunc(GL_LESS);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(1.5f, 2.0f);
  glUseProgram(shadow_.id());
  scene_.draw(shadow_.id(), eye);
  if (receiverMap_.texture() != 0) {
    glBindFramebuffer(GL_FRAMEBUFFER, receiverMap_.framebuffer());
    glClear(GL_DEPTH_BUFFER_BIT);
    scene_.draw(shadow_.id(), eye, GpuScene::DrawSet::NonCasters);
  }
  glDisable(GL_POLYGON_OFFSET_FILL);
  glPopDebugGroup();
  updateLightConstants(eye);
  drawLightMaps(eye);

  glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, -1, "sample.geometry");
  glBindFramebuffer(GL_FRAMEBUFFER, targets_.geometryFramebuffer());
  glViewport(0, 0, width, height);
  const float zero[4] = {0, 0, 0, 0};
  glClearBufferfv(GL_COLOR, 0, zero);
  glClearBufferfv(GL_COLOR, 1, zero);
  glClearDepth(0.0);  // reverse-Z: far is 0
  glClear(GL_DEPTH_BUFFER_BIT);
  glDepthFunc(GL_GREATER);
  glUseProgram(geometry_.id());
  glUniform3fv(glGetUniformLocation(geometry_.id(), "cameraWorld"), 1,
               glm::value_ptr(glm::vec3(eye)));
  scene_.draw(geometry_.id(), eye, GpuScene::DrawSet::Opaque);
  glPopDebugGroup();

  glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, -1, "sample.lighting");
  glDisable(GL_DEPTH_TEST);
  glBindFramebuffer(GL_FRAMEBUFFER, targets_.lightingFramebuffer());
  glUseProgram(lighting_.id());
  const GLuint lightingInputs[] = {targets_.depth(), targets_.normal(), targets_.albedo(),
                                   shadowMap_.texture()};
  glBindTextures(0, 4, lightingInputs);
  glBindBufferBase(GL_UNIFORM_BUFFER, 1, lightUniforms_.id());
  // Every unit of the lights' shadow array holds a depth texture, the sun's where unused.
  GLuint lightShadows[kMaxSceneLights];
  for (int i = 0; i < kMaxSceneLights; ++i)
    lightShadows[i] = size_t(i) < lightMaps_.size() ? lightMaps_[size_t(i)]->shadow.texture()
                                                    : shadowMap_.texture();
  glBindTextures(4, kMaxSceneLights, lightShadows);
  drawFullscreen(emptyVao_.id());
  glBindTextures(4, kMaxSceneLights, nullptr);
  glBindBufferBase(GL_UNIFORM_BUFFER, 1, 0);
  glPopDebugGroup();

  glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, -1, "sample.fog");
  glBindFramebuffer(GL_FRAMEBUFFER, foggedFbo_.id());
  glViewport(0, 0, width, height);
  glUseProgram(composite_.id());
  const GLuint fogInputs[] = {targets_.depth(), targets_.hdr()};
  glBindTextures(0, 2, fogInputs);
  drawFullscreen(emptyVao_.id());
  glPopDebugGroup();

  return true;
}

void Renderer::endFrame() {
  const int width = settings_.width, height = settings_.height;
  const glm::dvec3 eye = input_.camera.position;
  glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
  glBindBufferBase(GL_UNIFORM_BUFFER, 0, frameUniforms_.id());
  glBindFramebuffer(GL_FRAMEBUFFER, foggedFbo_.id());
  glViewport(0, 0, width, height);
  casterSurfaces_.drawMetal(scene_, eye, shadowMap_.texture());
  const bool glass = casterSurfaces_.hasGlass();
  if (glass) {
    glCopyImageSubData(targets_.depth(), GL_TEXTURE_2D, 0, 0, 0, 0, displayDepth_.id(),
                       GL_TEXTURE_2D, 0, 0, 0, 0, width, height, 1);
    casterSurfaces_.drawGlass(scene_, eye, fogged_.id(), sceneBelow_.id(), displayFbo_.id(),
                              targets_.depth(), shadowMap_.texture());
  }
  const GLuint surfaceDepth = glass ? displayDepth_.id() : targets_.depth();

  glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, -1, "sample.water_surface");
  glBindFramebuffer(GL_FRAMEBUFFER, glass ? displayFbo_.id() : foggedFbo_.id());
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_GREATER);
  glDepthMask(GL_FALSE);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  // The surface refracts the frame as it is now; it cannot read the target it draws into.
  glCopyImageSubData(fogged_.id(), GL_TEXTURE_2D, 0, 0, 0, 0, sceneBelow_.id(), GL_TEXTURE_2D, 0, 0,
                     0, 0, width, height, 1);
  glUseProgram(water_.id());
  const GLuint waterInputs[] = {ocean_->displacementTexture(), ocean_->slopeTexture()};
  glBindTextures(4, 2, waterInputs);
  const GLuint refractionInputs[] = {surfaceDepth, sceneBelow_.id()};
  glBindTextures(0, 2, refractionInputs);
  // A pool on land has no sea: only its own water is drawn, on a square of its own.
  const bool sea = !localWater_ || localWater_->seaVisible();
  if (sea) {
    setLocalWaterUniforms(eye, /*regionSquare=*/false);
    waterGrid_.draw();
  } else if (!localWater_->regions().empty()) {
    // One vertex a cell of the region's own grid (a simulation texel, for the pool's 256).
    if (regionGrid_.empty())
      regionGrid_.createSquare(std::clamp(localWater_->regions()[0].gridResolution, 16, 1024));
    setLocalWaterUniforms(eye, /*regionSquare=*/true);
    regionGrid_.draw();
  }
  glBindTextureUnit(6, 0);
  glDisable(GL_BLEND);
  glDisable(GL_DEPTH_TEST);
  glDepthMask(GL_TRUE);
  glPopDebugGroup();

  glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, -1, "sample.tonemap");
  glBindFramebuffer(GL_FRAMEBUFFER, outputFbo_.id());
  glUseProgram(tonemap_.id());
  glBindTextureUnit(0, fogged_.id());
  drawFullscreen(emptyVao_.id());
  glPopDebugGroup();

  glBindTextures(0, 6, nullptr);
  glUseProgram(0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void Renderer::setLocalWaterUniforms(const glm::dvec3& eye, bool regionSquare) {
  glm::vec4 frame(0.0f), extent(0.0f);
  if (localWater_ && !localWater_->regions().empty()) {
    const postfx::LocalWater& region = localWater_->regions()[0];
    // Relative to the camera in double: float never sees a region 1e6 m from the origin.
    const glm::dvec2 relative = region.centre - glm::dvec2(eye.x, eye.z);
    frame = glm::vec4(glm::vec2(relative), float(std::cos(region.rotation)),
                      float(-std::sin(region.rotation)));
    extent = glm::vec4(glm::vec2(1.0 / region.size),
                       region.mode == postfx::LocalWaterMode::Add ? 1.0f : 2.0f,
                       regionSquare ? 1.0f : 0.0f);
    glBindTextureUnit(6, region.texture.texture);
  }
  glUniform4fv(glGetUniformLocation(water_.id(), "localWaterFrame"), 1, glm::value_ptr(frame));
  glUniform4fv(glGetUniformLocation(water_.id(), "localWaterExtent"), 1, glm::value_ptr(extent));
}

void Renderer::presentTo(GLuint framebuffer, int width, int height) const {
  glBlitNamedFramebuffer(outputFbo_.id(), framebuffer, 0, 0, settings_.width, settings_.height, 0,
                         0, width, height, GL_COLOR_BUFFER_BIT, GL_LINEAR);
}

std::vector<uint8_t> Renderer::readColor() const {
  std::vector<uint8_t> pixels(size_t(settings_.width) * settings_.height * 4);
  glGetTextureImage(output_.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(pixels.size()),
                    pixels.data());
  return pixels;
}

std::vector<float> Renderer::readRadiance() const {
  std::vector<float> pixels(size_t(settings_.width) * settings_.height * 4);
  glGetTextureImage(fogged_.id(), 0, GL_RGBA, GL_FLOAT, GLsizei(pixels.size() * sizeof(float)),
                    pixels.data());
  return pixels;
}

}  // namespace ocean
