#include "reflected_caustics/reflected_caustics_pass.h"

#include <cmath>

#include <glkit/texture.h>

#include "core/frame_geometry.h"
#include "core/host_target.h"
#include "core/shader_library.h"
#include "core/shared_math.h"
#include "core/visibility.h"
#include "core/work_account.h"
#include "seabed_caustics/caustics_pass.h"
#include "seabed_caustics/lookup_work.h"

namespace postfx::detail {

Result ReflectedCausticsPass::init(const CreateDesc& desc, std::string& error) {
  Result r = field_.init(shaderDefines(desc), error);
  if (r != Result::Ok) return r;
  r = receivers_.init(shaderDefines(desc), error);
  if (r != Result::Ok) return r;
  // Its framebuffer holds the host's target alone: no raw output.
  r = buildPrograms(shaderDefines(desc),
                    {{light_,
                      "postfx.reflected_caustics.light",
                      {kFullScreenVertex,
                       {GL_FRAGMENT_SHADER, "postfx/reflected_caustics/reflected_caustics.frag"}},
                      "#undef POSTFX_RAW_OUTPUT\n#define POSTFX_RAW_OUTPUT 0\n"},
                     {lightOnDepth_,
                      "postfx.reflected_caustics.light_on_depth",
                      {kFullScreenVertex,
                       {GL_FRAGMENT_SHADER, "postfx/reflected_caustics/reflected_caustics.frag"}},
                      "#undef POSTFX_RAW_OUTPUT\n#define POSTFX_RAW_OUTPUT 0\n"
                      "#define REFLECTED_VIEW_DEPTH 1\n"}},
                    error);
  if (r != Result::Ok) return r;
  framebuffer_ = glkit::createFramebuffer("postfx.reflected_caustics.target");
  sampler_ = glkit::createSampler(GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE,
                                  "postfx.sampler.reflected_caustics");
  return Result::Ok;
}

Result ReflectedCausticsPass::reserve(const FrameDesc& frame, int targetWidth, int targetHeight,
                                      std::string& error) {
  if (frame.reflectedCaustics.landing == ReflectedLanding::ViewDepth) {
    field_.release();
    return receivers_.reserve(frame, targetWidth, targetHeight, error);
  }
  receivers_.release();
  return field_.reserve(frame, error);
}

Result ReflectedCausticsPass::prepare(const FrameDesc& frame, std::string& error) {
  if (!attachHostTarget(framebuffer_.id(), frame.target.texture, "reflected caustics", error)) {
    finish();
    return Result::GlError;
  }
  return Result::Ok;
}

void ReflectedCausticsPass::finish() {
  glNamedFramebufferTexture(framebuffer_.id(), GL_COLOR_ATTACHMENT0, 0, 0);
}

void ReflectedCausticsPass::draw(const FrameDesc& frame, const ValidatedTextures& textures,
                                 const SeabedInputs& inputs) {
  const ReflectedCausticsSettings& s = frame.reflectedCaustics;
  const bool onDepth = s.landing == ReflectedLanding::ViewDepth;
  ReflectedLayout onDepthLayout;
  if (onDepth) {
    onDepthLayout = reflectedLayout(frame);
    receivers_.draw(frame, textures, onDepthLayout, inputs);
  } else {
    field_.draw(frame, textures, inputs);
  }
  const ReflectedLayout& l = onDepth ? onDepthLayout : field_.layout();
  const glm::dvec3 sun = glm::normalize(frame.sun.direction);
  const float flatR = shared::fresnelReflectance(static_cast<float>(sun.y), frame.water.ior);
  // Where the pattern reaches: the field's window, or the receivers' outer grid's square.
  glm::dvec2 reachOrigin = l.windowOrigin;
  double reachSize = l.windowSize;
  if (onDepth) {
    const ReflectedReceiverPass::Grid outer = ReflectedReceiverPass::grids(l).level[1];
    reachOrigin = outer.origin;
    reachSize = outer.cell * outer.cells;
  }
  const glm::dvec2 centre =
      reachOrigin + 0.5 * reachSize - glm::dvec2(frame.camera.position.x, frame.camera.position.z);
  float heights[8] = {};
  for (int k = 0; k < l.layers; ++k) heights[k] = static_cast<float>(l.height[k]);
  const glm::vec3 scale = frame.sun.irradiance * (s.intensity * flatR);
  const GLuint program = onDepth ? lightOnDepth_.id() : light_.id();
  glProgramUniform4f(program, 0, static_cast<float>(centre.x), static_cast<float>(centre.y),
                     static_cast<float>(1.0 / reachSize), static_cast<float>(l.layers));
  glProgramUniform4fv(program, 1, 2, heights);
  glProgramUniform4f(program, 3, static_cast<float>(sun.x), static_cast<float>(-sun.y),
                     static_cast<float>(sun.z), s.maxHeight);
  glProgramUniform4f(program, 4, scale.x, scale.y, scale.z, s.includeMirrorMean ? 1.0f : 0.0f);
  glProgramUniform2f(program, 5, static_cast<float>(l.rise.x), static_cast<float>(l.rise.y));
  glProgramUniform1f(program, 6, s.maxIrradiance);

  // Back to the view's rectangle and the seabed state's full-screen vertex array.
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer_.id());
  glViewportIndexedf(0, static_cast<float>(textures.x), static_cast<float>(textures.y),
                     static_cast<float>(textures.width), static_cast<float>(textures.height));
  glBindTextureUnit(POSTFX_UNIT_IRRADIANCE, onDepth ? receivers_.texture() : field_.texture());
  glBindSampler(POSTFX_UNIT_IRRADIANCE, onDepth ? 0 : sampler_.id());
  glUseProgram(program);
  // reflected_caustics.frag on its full path (a lit pixel above the water): depth, normal,
  // albedo, the shadow map, then on the view's depth the 5 x 5 light around the pixel and its
  // own, and a gather of up to 13 x 13 pixels (depth and light each, as far as the light's
  // spread reaches: data-dependent); on the height layers two layers' two lookups of up to four
  // taps, three channels, each filtered and B-spline smoothed (5 fetches).
  const int shadow = inputs.shadow != 0 ? kShadowFetches : 0;
  const double fetches = 3 + shadow + (onDepth ? 26.0 + 13 * 13 * 2 : 2.0 * 2 * 4 * 3 * 5);
  TrafficList traffic = inputs.traffic(true);
  traffic.add(Traffic::read(onDepth ? receivers_.texture() : field_.texture()));
  work::drawArrays({"reflected_caustics.light", {}, {fetches, 0.0, true}, traffic}, GL_TRIANGLES, 0,
                   3);
}

bool reflectedCausticsHaveWork(const CreateDesc& create, const FrameDesc& frame) {
  const ReflectedCausticsSettings& s = frame.reflectedCaustics;
  if (!hasFeature(create.features, Feature::ReflectedCaustics) || !s.enabled ||
      !(s.intensity > 0.0f) || !(frame.sun.direction.y > 0.0) || frame.water.texture.texture == 0)
    return false;
  return frustumReachesAboveWater(viewToWorldRotation(frame.camera.view), frame.camera.projection,
                                  create.depthConvention,
                                  frame.water.level - frame.camera.position.y);
}

}  // namespace postfx::detail
