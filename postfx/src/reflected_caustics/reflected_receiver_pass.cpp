#include "reflected_caustics/reflected_receiver_pass.h"

#include <algorithm>
#include <cmath>

#include <glkit/texture.h>

#include "core/block_check.h"
#include "core/gl_sizes.h"
#include "core/shader_library.h"
#include "core/shared_math.h"
#include "core/work_account.h"
#include "seabed_caustics/caustics_pass.h"
#include "seabed_caustics/grid_layer_draw.h"
#include "seabed_caustics/lookup_work.h"
#include "seabed_caustics/tile_irradiance_pass.h"

namespace postfx::detail {

namespace {
// Highest receiver a ray is followed to, in maxHeights (the light fades to its mean above
// maxHeight over REFLECTED_TOP_FADE of it), and the longest path, in window sides.
constexpr double kFollowedHeight = 1.0 + double(shared::REFLECTED_TOP_FADE);
constexpr double kFollowedPath = 2.0;
// A triangle landing on less than this many square pixels is deposited as a point.
constexpr float kPointPixels = 2.0f;
}  // namespace

Result ReflectedReceiverPass::init(const std::string& defines, std::string& error) {
  Result r = buildPrograms(
      defines,
      {{rays_,
        "postfx.reflected_caustics.receiver_rays",
        {{GL_COMPUTE_SHADER, "postfx/reflected_caustics/reflected_receiver_rays.comp"}}},
       {triangles_,
        "postfx.reflected_caustics.receiver_triangles",
        {{GL_VERTEX_SHADER, "postfx/reflected_caustics/reflected_receiver_triangles.vert"},
         {GL_FRAGMENT_SHADER, "postfx/reflected_caustics/reflected_receiver_splat.frag"}}},
       {points_,
        "postfx.reflected_caustics.receiver_points",
        {{GL_VERTEX_SHADER, "postfx/reflected_caustics/reflected_receiver_points.vert"},
         {GL_FRAGMENT_SHADER, "postfx/reflected_caustics/reflected_receiver_splat.frag"}},
        "#define RECEIVER_POINTS 1\n"}},
      error);
  if (r != Result::Ok) return r;
  r = slopes_.init(defines, "postfx.reflected_caustics", error);
  if (r != Result::Ok) return r;
  framebuffer_ = glkit::createFramebuffer("postfx.reflected_caustics.receiver_framebuffer");
  vertexArray_ = glkit::createVertexArray("postfx.reflected_caustics.receiver_vao");
  return Result::Ok;
}

Result ReflectedReceiverPass::reserve(const FrameDesc& frame, int width, int height,
                                      std::string& error) {
  const ReflectedLayout l = reflectedLayout(frame);
  if (!(light_ && width_ == width && height_ == height)) {
    light_.reset();
    light_ = glkit::createTexture(GL_TEXTURE_2D, "postfx.reflected_caustics.receiver_light");
    glTextureStorage2D(light_.id(), 1, GL_RGBA32F, width, height);
    width_ = width;
    height_ = height;
    glNamedFramebufferTexture(framebuffer_.id(), GL_COLOR_ATTACHMENT0, light_.id(), 0);
  }
  slopes_.ensure(frame.caustics.tileUnresolvedSpread);
  const std::uint64_t side = std::uint64_t(l.resolution) + 1;
  const bool points = gridPoints_.ensure(side * side, "postfx.reflected_caustics.receiver_points");
  if (glkit::storedWidth(light_) != width || !points) {
    width_ = height_ = 0;
    error =
        "reflectedCaustics: the driver could not allocate the receivers' light (gridResolution " +
        std::to_string(l.resolution) + ", " + std::to_string(width) + "x" + std::to_string(height) +
        ")";
    return Result::OutOfMemory;
  }
  return Result::Ok;
}

ReflectedReceiverPass::Grids ReflectedReceiverPass::grids(const ReflectedLayout& l) {
  Grids g;
  g.level[0] = {l.windowOrigin, l.texel, l.resolution};
  // The outer grid: kOuterScale times the window's side and cell, centred on it, snapped to
  // whole outer cells times the window's own snap so its lines fall on the window's edges.
  const double cell = kOuterScale * l.texel;
  const double snap = cell * double(1 << shared::IRRADIANCE_MIP_LEVELS);
  const glm::dvec2 centre = l.windowOrigin + 0.5 * l.windowSize;
  g.level[1] = {glm::floor((centre - 0.5 * kOuterScale * l.windowSize) / snap) * snap, cell,
                l.resolution};
  return g;
}

void ReflectedReceiverPass::draw(const FrameDesc& frame, const ValidatedTextures& textures,
                                 const ReflectedLayout& l, const SeabedInputs& inputs) {
  const Grids g = grids(l);
  const float zeros[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  glClearTexSubImage(light_.id(), 0, 0, 0, 0, textures.width, textures.height, 1, GL_RGBA, GL_FLOAT,
                     zeros);
  work::noteClear("reflected_caustics.clear", std::uint64_t(textures.width) * textures.height * 16);
  // The inner grid's window is the outer grid's hole: every water point lights once.
  const glm::dvec2 camera(frame.camera.position.x, frame.camera.position.z);
  const glm::dvec2 holeMin = l.windowOrigin - camera, holeMax = holeMin + l.windowSize;
  drawGrid(frame, textures, g.level[1], 1, glm::vec4(holeMin.x, holeMin.y, holeMax.x, holeMax.y),
           inputs);
  // One buffer of grid points for both: the outer grid's draws read it before the window's rays
  // overwrite it (the barrier orders the two), and the slope statistics likewise.
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
  drawGrid(frame, textures, g.level[0], 0, glm::vec4(0.0f), inputs);
}

void ReflectedReceiverPass::drawGrid(const FrameDesc& frame, const ValidatedTextures& textures,
                                     const Grid& grid, int index, const glm::vec4& hole,
                                     const SeabedInputs& inputs) {
  const int pointsPerSide = grid.cells + 1;
  const WaterSurface& water = frame.water;
  const ReflectedCausticsSettings& s = frame.reflectedCaustics;
  const glm::dvec3 sun = glm::normalize(frame.sun.direction);
  const double flatR = shared::fresnelReflectance(static_cast<float>(sun.y), water.ior);
  const bool slopeSpread = frame.caustics.tileUnresolvedSpread;
  if (slopeSpread) slopes_.measure(frame, textures, grid.cell);
  const GLuint compute = rays_.id();
  const int texelsPerSide = std::max(textures.water.width, textures.water.height);
  glm::vec4 cascades[kMaxCascades];
  cascadeGridUniforms(water, grid.origin, grid.cell, texelsPerSide, cascades);
  glProgramUniform4fv(compute, 0, water.cascadeCount, &cascades[0].x);
  glProgramUniform1i(compute, 4, water.cascadeCount);
  const glm::dvec2 corner =
      grid.origin - glm::dvec2(frame.camera.position.x, frame.camera.position.z);
  glProgramUniform4f(compute, 5, static_cast<float>(corner.x), static_cast<float>(corner.y),
                     static_cast<float>(grid.cell),
                     static_cast<float>(water.level - frame.camera.position.y));
  glProgramUniform4f(compute, 6, static_cast<float>(sun.x), static_cast<float>(sun.y),
                     static_cast<float>(sun.z), water.ior);
  glProgramUniform4f(compute, 7, saturatedFloat(flatR > 0.0 ? 1.0 / flatR : 0.0),
                     static_cast<float>(kFollowedHeight * s.maxHeight),
                     static_cast<float>(kFollowedPath * s.windowSize), 0.0f);
  const double sunRadius = 0.5 * glm::radians(double(frame.sun.angularDiameterDegrees));
  glProgramUniform2f(compute, 8, static_cast<float>(0.25 * sunRadius * sunRadius),
                     slopeSpread ? 1.0f : 0.0f);
  glProgramUniform1i(compute, 9, pointsPerSide);
  glUseProgram(compute);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, POSTFX_STORAGE_GRID_POINTS, gridPoints_.buffer());
  const GLuint groups = static_cast<GLuint>((pointsPerSide + 15) / 16);
  // reflected_receiver_rays.comp per grid point: each cascade's water, then its mirrored ray
  // marched through the view's depth (data-dependent: up to 65 steps, a bisection of 8 where
  // it passes behind a surface, the landing pixel's plane from 5 depths), the shadow map.
  const int shadow = inputs.shadow != 0 ? kShadowFetches : 0;
  work::dispatchCompute(
      {"reflected_caustics.rays",
       {},
       {perInvocation(water.cascadeCount + shadow + 65 + 8 + 5,
                      double(pointsPerSide) * pointsPerSide, groups * groups * 256.0),
        0.0, true},
       {Traffic::read(water.texture.texture), Traffic::readLevel0(inputs.depth, inputs.share),
        Traffic::read(inputs.shadow), Traffic::writeBuffer(gridPoints_.buffer())}},
      groups, groups, 1);
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);

  // Flat water's flux through one grid triangle, in flat mirror light times m^2: the sun's
  // irradiance on the horizontal (sun.y) over half a cell, R(theta) relative to flat water's in
  // each point's weight.
  const float triangleFlux = static_cast<float>(sun.y * 0.5 * grid.cell * grid.cell);
  for (GLuint program : {triangles_.id(), points_.id()}) {
    glProgramUniform4f(program, 0, triangleFlux, s.maxIrradiance, kPointPixels,
                       static_cast<float>(pointsPerSide));
    glProgramUniform4fv(program, 1, 1, &hole.x);
    glProgramUniform3f(program, 3, static_cast<float>(sun.x), static_cast<float>(-sun.y),
                       static_cast<float>(sun.z));
    glProgramUniform4f(program, 2, static_cast<float>(corner.x), static_cast<float>(corner.y),
                       static_cast<float>(grid.cell), static_cast<float>(index));
  }
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer_.id());
  glViewportIndexedf(0, 0.0f, 0.0f, static_cast<float>(textures.width),
                     static_cast<float>(textures.height));
  glBindVertexArray(vertexArray_.id());
  glEnable(GL_PROGRAM_POINT_SIZE);
  glBindTextureUnit(POSTFX_UNIT_GRID_POINTS, gridPoints_.view());
  glBindSampler(POSTFX_UNIT_GRID_POINTS, 0);
  const GLsizei triangles = 2 * GLsizei(grid.cells) * GLsizei(grid.cells);
  // reflected_receiver_triangles.vert / _points.vert per vertex: its triangle's three grid
  // points (two texels each); reflected_receiver_splat.frag per fragment: the pixel's depth.
  const std::uint64_t gridBytes = std::uint64_t(pointsPerSide) * pointsPerSide * 32;
  const TrafficList drawTraffic{Traffic::readBytes(gridBytes),
                                Traffic::readLevel0(inputs.depth, inputs.share)};
  glUseProgram(triangles_.id());
  work::drawArrays({"reflected_caustics.landing_triangles", {6.0, 0.0}, {1.0, 0.0}, drawTraffic},
                   GL_TRIANGLES, 0, 3 * triangles);
  glUseProgram(points_.id());
  work::drawArrays({"reflected_caustics.landing_points", {6.0, 0.0}, {1.0, 0.0}, drawTraffic},
                   GL_POINTS, 0, 3 * triangles);
}

void ReflectedReceiverPass::release() {
  light_.reset();
  slopes_.ensure(false);
  width_ = height_ = 0;
  gridPoints_.reset();
}

std::uint64_t ReflectedReceiverPass::allocatedBytes() const {
  return textureBytes(light_.id(), 16) + bufferBytes(gridPoints_.buffer()) +
         slopes_.allocatedBytes();
}

}  // namespace postfx::detail
