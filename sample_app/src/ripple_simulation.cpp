#include "ripple_simulation.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>

#include <glkit/texture.h>

namespace ocean_sample {
const glkit::ShaderLibrary& shaderLibrary();
}

namespace ocean {
namespace {

constexpr int kGroup = 8;  // the compute shaders' local size, both axes
constexpr double kCourant = 0.5;
constexpr int kMaxStepsPerSecond = 100000;
constexpr int kMaxStepsPerCall = 100000;

glkit::Program buildCompute(const char* path, const char* label, std::string& error) {
  return glkit::buildProgram(ocean_sample::shaderLibrary(), {{GL_COMPUTE_SHADER, path}}, "", label,
                             error);
}

bool finite(glm::dvec3 v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

bool inRange(double value, double lo, double hi) {
  return value >= lo && value <= hi;  // false for NaN
}

}  // namespace

std::unique_ptr<RippleSimulation> RippleSimulation::create(const RippleDesc& desc,
                                                           std::string& error) {
  if (desc.resolution < 16 || desc.resolution > 2048) {
    error =
        "ripple simulation: resolution " + std::to_string(desc.resolution) + " outside [16, 2048]";
    return nullptr;
  }
  if (!inRange(desc.size.x, 0.05, 1e4) || !inRange(desc.size.y, 0.05, 1e4)) {
    error = "ripple simulation: size outside [0.05, 1e4] m";
    return nullptr;
  }
  if (!(desc.waveSpeed > 0.0 && desc.waveSpeed <= 50.0)) {
    error = "ripple simulation: waveSpeed outside (0, 50] m/s";
    return nullptr;
  }
  if (!inRange(desc.damping, 0.0, 100.0)) {
    error = "ripple simulation: damping outside [0, 100] 1/s";
    return nullptr;
  }
  if (!(desc.maxHeight > 0.0 && desc.maxHeight <= 100.0)) {
    error = "ripple simulation: maxHeight outside (0, 100] m";
    return nullptr;
  }
  if (!inRange(desc.absorbingEdge, 0.0, 0.5 * std::min(desc.size.x, desc.size.y))) {
    error = "ripple simulation: absorbingEdge outside [0, half the shorter side] m";
    return nullptr;
  }
  std::unique_ptr<RippleSimulation> sim(new RippleSimulation());
  sim->desc_ = desc;
  // The largest stable step is 1 / (c sqrt(1/dx^2 + 1/dz^2)); take kCourant of it, rounded down
  // to a whole number of steps per second.
  const glm::dvec2 texel = desc.size / double(desc.resolution);
  const double limit =
      desc.waveSpeed * std::sqrt(1.0 / (texel.x * texel.x) + 1.0 / (texel.y * texel.y));
  double perSecond = std::ceil(limit / kCourant);
  // The velocity's diffusion is explicit too: stable for nu dt (4/dx^2 + 4/dz^2) <= 2, kept at
  // half of that.
  if (!(desc.viscosity >= 0.0 && desc.viscosity <= 1e3)) {
    error = "ripple simulation: viscosity outside [0, 1e3] m^2/s";
    return nullptr;
  }
  const double diffusion =
      4.0 * desc.viscosity * (1.0 / (texel.x * texel.x) + 1.0 / (texel.y * texel.y));
  perSecond = std::max(perSecond, std::ceil(diffusion));
  if (perSecond > kMaxStepsPerSecond) {
    error = "ripple simulation: " + std::to_string(std::llround(perSecond)) +
            " steps a second needed (waveSpeed over texel size), over " +
            std::to_string(kMaxStepsPerSecond);
    return nullptr;
  }
  sim->stepsPerSecond_ = std::max(1, int(perSecond));
  sim->stepProgram_ = buildCompute("sample/ripple_step.comp", "sample.ripple_step", error);
  if (!sim->stepProgram_) return nullptr;
  sim->dropProgram_ = buildCompute("sample/ripple_drop.comp", "sample.ripple_drop", error);
  if (!sim->dropProgram_) return nullptr;
  sim->sphereProgram_ = buildCompute("sample/ripple_sphere.comp", "sample.ripple_sphere", error);
  if (!sim->sphereProgram_) return nullptr;
  sim->slopeProgram_ = buildCompute("sample/ripple_slopes.comp", "sample.ripple_slopes", error);
  if (!sim->slopeProgram_) return nullptr;
  sim->shiftProgram_ = buildCompute("sample/ripple_shift.comp", "sample.ripple_shift", error);
  if (!sim->shiftProgram_) return nullptr;
  const int n = desc.resolution;
  for (int i = 0; i < 2; ++i)
    sim->state_[i] = glkit::createTexture2D(GL_RG32F, n, n, GL_NEAREST, "sample.ripple_state");
  // Linear: the water surface samples it between texels (the plugin uses its own sampler).
  sim->output_ = glkit::createTexture2D(GL_RGBA32F, n, n, GL_LINEAR, "sample.ripple_water");
  if (glkit::storedWidth(sim->output_) != n || glkit::storedWidth(sim->state_[1]) != n) {
    error = "ripple simulation: the driver refused its textures";
    return nullptr;
  }
  sim->reset();
  return sim;
}

glm::vec2 RippleSimulation::texelSize() const {
  return glm::vec2(desc_.size / double(desc_.resolution));
}

void RippleSimulation::reset() {
  const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  for (glkit::Texture& state : state_) glClearTexImage(state.id(), 0, GL_RG, GL_FLOAT, zero);
  glClearTexImage(output_.id(), 0, GL_RGBA, GL_FLOAT, zero);
  current_ = 0;
  stale_ = false;
}

void RippleSimulation::bindState(GLuint program) {
  glUseProgram(program);
  glUniform2fv(glGetUniformLocation(program, "texelMetres"), 1, glm::value_ptr(texelSize()));
  glUniform2fv(glGetUniformLocation(program, "sizeMetres"), 1,
               glm::value_ptr(glm::vec2(desc_.size)));
  glUniform1f(glGetUniformLocation(program, "maxHeight"), float(desc_.maxHeight));
  glBindImageTexture(0, state_[current_].id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_RG32F);
}

namespace {

void dispatchOver(int resolution) {
  const GLuint groups = GLuint((resolution + kGroup - 1) / kGroup);
  glDispatchCompute(groups, groups, 1);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

void unbind() {
  glBindImageTexture(0, 0, 0, GL_FALSE, 0, GL_READ_ONLY, GL_RG32F);
  glBindImageTexture(1, 0, 0, GL_FALSE, 0, GL_READ_ONLY, GL_RG32F);
  glUseProgram(0);
}

}  // namespace

bool RippleSimulation::addDrop(glm::dvec2 centre, double radius, double strength) {
  if (!std::isfinite(centre.x) || !std::isfinite(centre.y) || !std::isfinite(radius) ||
      !std::isfinite(strength))
    return false;
  const glm::vec2 texel = texelSize();
  radius =
      std::clamp(radius, double(std::max(texel.x, texel.y)), std::max(desc_.size.x, desc_.size.y));
  strength = std::clamp(strength, -desc_.maxHeight, desc_.maxHeight);
  // Far outside the rectangle: float keeps the bump's shape, not 1e300 m.
  centre = glm::clamp(centre, -desc_.size * 2.0, desc_.size * 2.0);
  glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, -1, "sample.ripple_drop");
  const GLuint program = dropProgram_.id();
  bindState(program);
  glUniform2fv(glGetUniformLocation(program, "centre"), 1, glm::value_ptr(glm::vec2(centre)));
  glUniform1f(glGetUniformLocation(program, "radius"), float(radius));
  glUniform1f(glGetUniformLocation(program, "strength"), float(strength));
  dispatchOver(desc_.resolution);
  unbind();
  glPopDebugGroup();
  stale_ = true;
  return true;
}

bool RippleSimulation::moveSphere(glm::dvec3 from, glm::dvec3 to, double radius) {
  if (!finite(from) || !finite(to) || !std::isfinite(radius)) return false;
  if (!(radius > 0.0)) return false;
  radius = std::min(radius, std::max(desc_.size.x, desc_.size.y));
  const glm::dvec3 bound(desc_.size.x * 2.0, desc_.size.x + desc_.size.y, desc_.size.y * 2.0);
  from = glm::clamp(from, -bound, bound);
  to = glm::clamp(to, -bound, bound);
  glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, -1, "sample.ripple_sphere");
  const GLuint program = sphereProgram_.id();
  bindState(program);
  glUniform3fv(glGetUniformLocation(program, "fromCentre"), 1, glm::value_ptr(glm::vec3(from)));
  glUniform3fv(glGetUniformLocation(program, "toCentre"), 1, glm::value_ptr(glm::vec3(to)));
  glUniform1f(glGetUniformLocation(program, "radius"), float(radius));
  dispatchOver(desc_.resolution);
  unbind();
  glPopDebugGroup();
  stale_ = true;
  return true;
}

void RippleSimulation::step(int count) {
  count = std::clamp(count, 0, kMaxStepsPerCall);
  if (count == 0) return;
  glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, -1, "sample.ripple_step");
  const GLuint program = stepProgram_.id();
  glUseProgram(program);
  const double dt = stepSeconds();
  const glm::dvec2 texel = desc_.size / double(desc_.resolution);
  // (c dt / dx)^2 per axis: the Laplacian's weights, with dt folded in (see the shader).
  const glm::dvec2 courant = desc_.waveSpeed * dt / texel;
  glUniform2fv(glGetUniformLocation(program, "courantSquared"), 1,
               glm::value_ptr(glm::vec2(courant * courant)));
  glUniform1f(glGetUniformLocation(program, "damping"), float(desc_.damping));
  // The sponge's width in texels along u and v (0: reflecting walls everywhere).
  glUniform2fv(glGetUniformLocation(program, "spongeTexels"), 1,
               glm::value_ptr(glm::vec2(desc_.absorbingEdge / texel)));
  glUniform1f(glGetUniformLocation(program, "maxHeight"), float(desc_.maxHeight));
  glUniform1f(glGetUniformLocation(program, "stepSeconds"), float(dt));
  const glm::dvec2 viscosity = desc_.viscosity * dt / (texel * texel);
  glUniform2fv(glGetUniformLocation(program, "viscosityWeights"), 1,
               glm::value_ptr(glm::vec2(viscosity)));
  for (int i = 0; i < count; ++i) {
    glBindImageTexture(0, state_[current_].id(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_RG32F);
    glBindImageTexture(1, state_[1 - current_].id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RG32F);
    dispatchOver(desc_.resolution);
    current_ = 1 - current_;
  }
  unbind();
  glPopDebugGroup();
  stale_ = true;
}

void RippleSimulation::shift(glm::ivec2 texels) {
  if (texels == glm::ivec2(0)) return;
  const int n = desc_.resolution;
  texels = glm::clamp(texels, glm::ivec2(-n), glm::ivec2(n));
  glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, -1, "sample.ripple_shift");
  const GLuint program = shiftProgram_.id();
  glUseProgram(program);
  glUniform2i(glGetUniformLocation(program, "offset"), texels.x, texels.y);
  glBindImageTexture(0, state_[current_].id(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_RG32F);
  glBindImageTexture(1, state_[1 - current_].id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RG32F);
  dispatchOver(n);
  current_ = 1 - current_;
  unbind();
  glPopDebugGroup();
  stale_ = true;
}

GLuint RippleSimulation::texture() {
  if (stale_) updateSlopes();
  return output_.id();
}

void RippleSimulation::updateSlopes() {
  stale_ = false;
  glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, -1, "sample.ripple_slopes");
  const GLuint program = slopeProgram_.id();
  bindState(program);
  glBindImageTexture(1, output_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  const GLuint groups = GLuint((desc_.resolution + kGroup - 1) / kGroup);
  glDispatchCompute(groups, groups, 1);
  // Read next by the water surface, the plugin and read(): as a texture and by transfers.
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT |
                  GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  unbind();
  glPopDebugGroup();
}

std::vector<glm::vec4> RippleSimulation::read() {
  texture();
  const size_t n = size_t(desc_.resolution);
  std::vector<glm::vec4> texels(n * n);
  glGetTextureImage(output_.id(), 0, GL_RGBA, GL_FLOAT, GLsizei(texels.size() * sizeof(glm::vec4)),
                    texels.data());
  return texels;
}

}  // namespace ocean
