#include "object_caustics/object_caustics_pass.h"

#include <glkit/texture.h>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cstring>

#include "core/host_target.h"
#include "core/shader_library.h"
#include "core/shared_math.h"
#include "core/work_account.h"
#include "object_caustics/object_caustics_state.h"

namespace postfx::detail {
namespace {

// Each step binds its textures and samplers in one call from its first unit.
static_assert(POSTFX_OBJECT_UNIT_FRONT_NORMAL == POSTFX_OBJECT_UNIT_FRONT_POSITION + 1 &&
                  POSTFX_OBJECT_UNIT_BACK_POSITION == POSTFX_OBJECT_UNIT_FRONT_POSITION + 2 &&
                  POSTFX_OBJECT_UNIT_BACK_NORMAL == POSTFX_OBJECT_UNIT_FRONT_POSITION + 3 &&
                  POSTFX_OBJECT_UNIT_SPLAT_RECEIVER_DEPTH == POSTFX_OBJECT_UNIT_FRONT_POSITION + 4,
              "the splat's units are consecutive");
static_assert(POSTFX_OBJECT_UNIT_HISTORY_MAP == POSTFX_OBJECT_UNIT_CURRENT_MAP + 1,
              "the temporal filter's units are consecutive");
static_assert(POSTFX_UNIT_NORMAL == POSTFX_UNIT_DEPTH + 1 &&
                  POSTFX_UNIT_ALBEDO == POSTFX_UNIT_DEPTH + 2 &&
                  POSTFX_OBJECT_UNIT_CAUSTIC_MAP == POSTFX_UNIT_DEPTH + 3 &&
                  POSTFX_OBJECT_UNIT_RECEIVER_DEPTH == POSTFX_UNIT_DEPTH + 4,
              "the composite's units are consecutive");
// Uniform locations of object_caustics_caster.* and object_caustics_temporal.frag.
enum CasterUniform : GLint {
  kModelToAnchor = 0,
  kNormalToWorld = 1,
  kCasterIndex = 2,
  kBackFaces = 3,
  kFlatNormals = 4
};
constexpr GLint kHistoryWeight = 0;

glkit::Texture makeTexture(GLenum format, int size, const char* name) {
  glkit::Texture texture = glkit::createTexture(GL_TEXTURE_2D, name);
  glTextureStorage2D(texture.id(), 1, format, size, size);
  return texture;
}

}  // namespace

Result ObjectCausticsPass::init(const std::string& defines, int maxLocalLights, bool volume,
                                std::string& error) {
  const Result r = buildPrograms(
      defines,
      {{caster_,
        "postfx.object_caustics.caster",
        {{GL_VERTEX_SHADER, "postfx/object_caustics/object_caustics_caster.vert"},
         {GL_FRAGMENT_SHADER, "postfx/object_caustics/object_caustics_caster.frag"}}},
       {trace_,
        "postfx.object_caustics.trace",
        {{GL_COMPUTE_SHADER, "postfx/object_caustics/object_caustics_trace.comp"}}},
       {splat_,
        "postfx.object_caustics.splat",
        {{GL_VERTEX_SHADER, "postfx/object_caustics/object_caustics_splat.vert"},
         {GL_FRAGMENT_SHADER, "postfx/object_caustics/object_caustics_splat.frag"}}},
       {temporal_,
        "postfx.object_caustics.temporal",
        {kFullScreenVertex,
         {GL_FRAGMENT_SHADER, "postfx/object_caustics/object_caustics_temporal.frag"}}},
       {composite_,
        "postfx.object_caustics.composite",
        {kFullScreenVertex,
         {GL_FRAGMENT_SHADER, "postfx/object_caustics/object_caustics_composite.frag"}}}},
      error);
  if (r != Result::Ok) return r;
  if (volume) {
    const glkit::ShaderStage vertex{GL_VERTEX_SHADER,
                                    "postfx/object_caustics/volume_caustics.vert"};
    const glkit::ShaderStage fragment{GL_FRAGMENT_SHADER,
                                      "postfx/object_caustics/volume_caustics.frag"};
    const Result v = buildPrograms(
        defines,
        {{volumeBeams_,
          "postfx.volume_caustics.beams",
          {vertex, fragment},
          "#define POSTFX_VOLUME_LINES 0\n"},
         {volumeLines_,
          "postfx.volume_caustics.lines",
          {vertex, fragment},
          "#define POSTFX_VOLUME_LINES 1\n"},
         {volumeResolve_,
          "postfx.volume_caustics.resolve",
          {kFullScreenVertex,
           {GL_FRAGMENT_SHADER, "postfx/object_caustics/volume_caustics_resolve.frag"}}}},
        error);
    if (v != Result::Ok) return v;
    volumeFbo_ = glkit::createFramebuffer("postfx.volume_caustics.light");
  }
  meshVao_ = glkit::createVertexArray("postfx.object_caustics.mesh_vao");
  glEnableVertexArrayAttrib(meshVao_.id(), 0);
  glVertexArrayAttribBinding(meshVao_.id(), 0, 0);
  glVertexArrayAttribBinding(meshVao_.id(), 1, 0);
  emptyVao_ = glkit::createVertexArray("postfx.object_caustics.empty_vao");
  GLint alignment = 256;
  glGetIntegerv(GL_UNIFORM_BUFFER_OFFSET_ALIGNMENT, &alignment);
  alignment = std::max(alignment, 1);
  const GLintptr size = sizeof(shared::ObjectCausticsBlock);
  blockStride_ = (size + alignment - 1) / alignment * alignment;
  blockCapacity_ = static_cast<std::size_t>(1 + maxLocalLights);
  uniformBuffer_ =
      glkit::createBuffer(blockStride_ * static_cast<GLintptr>(blockCapacity_), nullptr,
                          GL_DYNAMIC_STORAGE_BIT, "postfx.object_caustics.block");
  frontFbo_ = glkit::createFramebuffer("postfx.object_caustics.front");
  backFbo_ = glkit::createFramebuffer("postfx.object_caustics.back");
  splatFbo_ = glkit::createFramebuffer("postfx.object_caustics.splat");
  temporalFbo_ = glkit::createFramebuffer("postfx.object_caustics.temporal");
  compositeFbo_ = glkit::createFramebuffer("postfx.object_caustics.composite");
  lightFbo_ = glkit::createFramebuffer("postfx.object_caustics.light_splat");
  const GLenum two[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
  glNamedFramebufferDrawBuffers(frontFbo_.id(), 2, two);
  glNamedFramebufferDrawBuffers(backFbo_.id(), 2, two);
  pointSampler_ = glkit::createSampler(GL_NEAREST, GL_NEAREST, GL_CLAMP_TO_EDGE,
                                       "postfx.object_caustics.sampler.point");
  linearSampler_ = glkit::createSampler(GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE,
                                        "postfx.object_caustics.sampler.linear");
  return Result::Ok;
}

void ObjectCausticsPass::ensureGrid(int size) {
  if (size == gridSize_) return;
  // The old size goes first: never two of them allocated at once.
  for (glkit::Texture* t :
       {&frontPosition_, &frontNormal_, &backPosition_, &backNormal_, &casterDepth_})
    t->reset();
  // Positions in float: the hit search differences them over the caster's size.
  frontPosition_ = makeTexture(GL_RGBA32F, size, "postfx.object_caustics.front_position");
  frontNormal_ = makeTexture(GL_RGBA16F, size, "postfx.object_caustics.front_normal");
  backPosition_ = makeTexture(GL_RGBA32F, size, "postfx.object_caustics.back_position");
  backNormal_ = makeTexture(GL_RGBA16F, size, "postfx.object_caustics.back_normal");
  casterDepth_ = makeTexture(GL_DEPTH_COMPONENT32F, size, "postfx.object_caustics.depth");
  glNamedFramebufferTexture(frontFbo_.id(), GL_COLOR_ATTACHMENT0, frontPosition_.id(), 0);
  glNamedFramebufferTexture(frontFbo_.id(), GL_COLOR_ATTACHMENT1, frontNormal_.id(), 0);
  glNamedFramebufferTexture(frontFbo_.id(), GL_DEPTH_ATTACHMENT, casterDepth_.id(), 0);
  glNamedFramebufferTexture(backFbo_.id(), GL_COLOR_ATTACHMENT0, backPosition_.id(), 0);
  glNamedFramebufferTexture(backFbo_.id(), GL_COLOR_ATTACHMENT1, backNormal_.id(), 0);
  glNamedFramebufferTexture(backFbo_.id(), GL_DEPTH_ATTACHMENT, casterDepth_.id(), 0);
  gridSize_ = size;
}

void ObjectCausticsPass::ensureLandings(int size, int layers) {
  if (glkit::storedWidth(landings_) == size && layers == landingLayers_) return;
  landings_.reset();  // the old size goes first
  landings_ = glkit::createTexture(GL_TEXTURE_2D_ARRAY, "postfx.object_caustics.landings");
  glTextureStorage3D(landings_.id(), 1, GL_RGBA32F, size, size, layers);
  landingLayers_ = layers;
}

void ObjectCausticsPass::ensureVolumeLight(int width, int height) {
  if (width == volumeWidth_ && height == volumeHeight_) return;
  volumeLight_.reset();  // the old size goes first
  volumeLight_ = glkit::createTexture(GL_TEXTURE_2D, "postfx.volume_caustics.light");
  glTextureStorage2D(volumeLight_.id(), 1, GL_RGBA32F, width, height);
  glNamedFramebufferTexture(volumeFbo_.id(), GL_COLOR_ATTACHMENT0, volumeLight_.id(), 0);
  volumeWidth_ = width;
  volumeHeight_ = height;
}

void ObjectCausticsPass::ensureMap(int size) {
  if (size == mapSize_) return;
  for (glkit::Texture* t : {&splatMap_, &history_[0], &history_[1]}) t->reset();
  // RGBA32F: a focus texel sums thousands of splats; half floats would round them away.
  splatMap_ = makeTexture(GL_RGBA32F, size, "postfx.object_caustics.splats");
  history_[0] = makeTexture(GL_RGBA32F, size, "postfx.object_caustics.filtered_a");
  history_[1] = makeTexture(GL_RGBA32F, size, "postfx.object_caustics.filtered_b");
  glNamedFramebufferTexture(splatFbo_.id(), GL_COLOR_ATTACHMENT0, splatMap_.id(), 0);
  mapSize_ = size;
  historyValid_ = false;
}

void ObjectCausticsPass::ensureLightMap(int size) {
  if (size == lightMapSize_) return;
  lightMap_.reset();
  lightMap_ = makeTexture(GL_RGBA32F, size, "postfx.object_caustics.light_splats");
  glNamedFramebufferTexture(lightFbo_.id(), GL_COLOR_ATTACHMENT0, lightMap_.id(), 0);
  lightMapSize_ = size;
}

Result ObjectCausticsPass::prepare(const FrameDesc& frame, const ObjectCausticsViews& views,
                                   std::span<const ObjectCausticsTarget> targets,
                                   std::string& error) {
  const ObjectCausticsSettings& s = frame.objectCaustics.settings;
  const shared::ObjectCausticsBlock& block = views.blocks[views.sun ? 0 : 1];
  dispersed_ = block.receiver.w > 0.5f;
  volume_ = views.volume;
  volumeMethod_ = s.volume.method;
  // Each channel's landing and flux, then (volume caustics) each one's segment and power.
  const int channels = dispersed_ ? 3 : 1;
  ensureLandings(s.gridSize, channels * (volume_ ? 5 : 2));
  ensureGrid(s.gridSize);
  if (views.sun) ensureMap(s.mapSize);
  if (!views.lights.empty()) ensureLightMap(s.mapSize);
  // Storage the driver refused (GL_OUT_OF_MEMORY) leaves a map without levels and its
  // framebuffer incomplete: found here, before any pass adds light.
  if ((views.sun && (glkit::storedWidth(history_[0]) != s.mapSize ||
                     glkit::storedWidth(history_[1]) != s.mapSize)) ||
      (!views.lights.empty() && glkit::storedWidth(lightMap_) != s.mapSize)) {
    error = "objectCaustics: the driver could not allocate the caustic map (mapSize " +
            std::to_string(s.mapSize) + ")";
    return Result::OutOfMemory;
  }
  if (volume_) {
    int width = 0, height = 0;
    for (const ObjectCausticsTarget& target : targets)
      width = std::max(width, target.rect.width), height = std::max(height, target.rect.height);
    ensureVolumeLight(width, height);
    if (glCheckNamedFramebufferStatus(volumeFbo_.id(), GL_DRAW_FRAMEBUFFER) !=
        GL_FRAMEBUFFER_COMPLETE) {
      volumeWidth_ = volumeHeight_ = 0;
      error = "objectCaustics: the driver could not allocate the volume caustics' light (" +
              std::to_string(width) + "x" + std::to_string(height) + ")";
      return Result::OutOfMemory;
    }
  }
  if (glkit::storedWidth(landings_) != s.gridSize) {
    error = "objectCaustics: the driver could not allocate the ray landings (gridSize " +
            std::to_string(s.gridSize) + ")";
    return Result::OutOfMemory;
  }
  // The caster maps always; the sun's splat map and the lights' when this frame draws them.
  const GLuint splatFbo = views.sun ? splatFbo_.id() : 0;
  const GLuint lightFbo = views.lights.empty() ? 0 : lightFbo_.id();
  for (GLuint fbo : {frontFbo_.id(), backFbo_.id(), splatFbo, lightFbo}) {
    if (fbo != 0 &&
        glCheckNamedFramebufferStatus(fbo, GL_DRAW_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
      error =
          "objectCaustics: an internal framebuffer is incomplete (could the driver not "
          "allocate the maps? mapSize " +
          std::to_string(s.mapSize) + ", gridSize " + std::to_string(s.gridSize) + ")";
      return Result::OutOfMemory;
    }
  }
  for (const ObjectCausticsTarget& target : targets) {
    if (!attachHostTarget(compositeFbo_.id(), target.frame->target.texture, "object caustics",
                          error)) {
      glNamedFramebufferTexture(compositeFbo_.id(), GL_COLOR_ATTACHMENT0, 0, 0);
      return Result::GlError;
    }
  }
  // One upload: camera view v's sun block in slot v * slotsPerView, light k's after it.
  const std::size_t slots = views.blocks.size();
  if (slots > blockCapacity_) {
    glkit::Buffer grown =
        glkit::createBuffer(blockStride_ * static_cast<GLintptr>(slots), nullptr,
                            GL_DYNAMIC_STORAGE_BIT, "postfx.object_caustics.block");
    GLint64 stored = 0;
    glGetNamedBufferParameteri64v(grown.id(), GL_BUFFER_SIZE, &stored);
    if (stored < blockStride_ * static_cast<GLint64>(slots)) {
      error = "objectCaustics: the driver could not allocate the views' constant blocks";
      return Result::OutOfMemory;
    }
    uniformBuffer_ = std::move(grown);
    blockCapacity_ = slots;
  }
  std::vector<unsigned char> bytes(static_cast<std::size_t>(blockStride_) * slots);
  for (std::size_t i = 0; i < slots; ++i)
    std::memcpy(bytes.data() + i * blockStride_, &views.blocks[i], sizeof(views.blocks[i]));
  glNamedBufferSubData(uniformBuffer_.id(), 0, static_cast<GLsizeiptr>(bytes.size()), bytes.data());
  slotsPerView_ = views.slotsPerView();
  lights_ = views.lights;
  if (!views.sun) return Result::Ok;
  const ObjectCausticMap placement = describeObjectCausticMap(views.sunFrame, s.mapSize);
  // The history is only meaningful in the same texel grid.
  if (!(placement.origin == placement_.origin && placement.axisU == placement_.axisU &&
        placement.axisV == placement_.axisV && placement.size == placement_.size))
    historyValid_ = false;
  placement_ = placement;
  light_ = views.sunFrame;
  return Result::Ok;
}

void ObjectCausticsPass::bindBlock(int slot) {
  glBindBufferRange(GL_UNIFORM_BUFFER, POSTFX_OBJECT_CAUSTICS_BLOCK_BINDING, uniformBuffer_.id(),
                    blockStride_ * slot, sizeof(shared::ObjectCausticsBlock));
}

void ObjectCausticsPass::drawCasterMaps(const FrameDesc& frame, const ObjectLightFrame& view) {
  const ObjectCausticsFrame& objects = frame.objectCaustics;
  const float size = static_cast<float>(gridSize_);
  glViewportIndexedf(0, 0.0f, 0.0f, size, size);
  glEnable(GL_DEPTH_TEST);
  glDepthMask(GL_TRUE);
  glUseProgram(caster_.id());
  glBindVertexArray(meshVao_.id());
  const GLuint program = caster_.id();
  const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  // Two RGBA32F maps and a 32-bit depth per side.
  const std::uint64_t mapBytes = std::uint64_t(gridSize_) * gridSize_ * (16 + 16 + 4);
  for (int side = 0; side < 2; ++side) {
    const bool back = side == 1;
    const GLuint fbo = back ? backFbo_.id() : frontFbo_.id();
    const float clearDepth = back ? 0.0f : 1.0f;
    glClearNamedFramebufferfv(fbo, GL_COLOR, 0, zero);
    glClearNamedFramebufferfv(fbo, GL_COLOR, 1, zero);
    glClearNamedFramebufferfv(fbo, GL_DEPTH, 0, &clearDepth);
    work::noteClear("object_caustics.caster_maps_clear", mapBytes);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fbo);
    glDepthFunc(back ? GL_GREATER : GL_LESS);
    glProgramUniform1i(program, kBackFaces, back ? 1 : 0);
    for (int c = 0; c < objects.casterCount; ++c) {
      if (!((view.casters >> c) & 1u)) continue;  // beyond a local light's reach
      const CasterMesh& m = objects.casters[c];
      const glm::mat4 modelToAnchor = casterModelToAnchor(view, m);
      const glm::mat4 normalToWorld = casterNormalToWorld(m);
      glProgramUniformMatrix4fv(program, kModelToAnchor, 1, GL_FALSE,
                                glm::value_ptr(modelToAnchor));
      glProgramUniformMatrix4fv(program, kNormalToWorld, 1, GL_FALSE,
                                glm::value_ptr(normalToWorld));
      glProgramUniform1i(program, kCasterIndex, c);
      const bool normals = m.normalOffset >= 0;
      glProgramUniform1i(program, kFlatNormals, normals ? 0 : 1);
      glVertexArrayVertexBuffer(meshVao_.id(), 0, m.vertexBuffer,
                                static_cast<GLintptr>(m.baseOffset), m.stride);
      glVertexArrayAttribFormat(meshVao_.id(), 0, 3, GL_FLOAT, GL_FALSE,
                                static_cast<GLuint>(m.positionOffset));
      if (normals) {
        glEnableVertexArrayAttrib(meshVao_.id(), 1);
        glVertexArrayAttribFormat(meshVao_.id(), 1, 3, GL_FLOAT, GL_FALSE,
                                  static_cast<GLuint>(m.normalOffset));
      } else {
        glDisableVertexArrayAttrib(meshVao_.id(), 1);
      }
      // object_caustics_caster.vert / .frag: the mesh's attributes, no fetches.
      const std::uint64_t indexBytes = m.indexBuffer == 0                                      ? 0
                                       : static_cast<GLenum>(m.indexType) == GL_UNSIGNED_INT   ? 4
                                       : static_cast<GLenum>(m.indexType) == GL_UNSIGNED_SHORT ? 2
                                                                                               : 1;
      const Step casterStep{"object_caustics.caster_maps",
                            {},
                            {},
                            {Traffic::readBytes(std::uint64_t(m.vertexCount) * m.stride +
                                                std::uint64_t(m.indexCount) * indexBytes)}};
      if (m.indexBuffer != 0) {
        glVertexArrayElementBuffer(meshVao_.id(), m.indexBuffer);
        work::drawElements(
            casterStep, GL_TRIANGLES, static_cast<GLsizei>(m.indexCount),
            static_cast<GLenum>(m.indexType),
            reinterpret_cast<const void*>(static_cast<std::intptr_t>(m.indexOffset)));
      } else {
        glVertexArrayElementBuffer(meshVao_.id(), 0);
        work::drawArrays(casterStep, GL_TRIANGLES, 0, static_cast<GLsizei>(m.vertexCount));
      }
    }
  }
  // Our VAO must not keep the host's buffers alive after the call.
  glVertexArrayVertexBuffer(meshVao_.id(), 0, 0, 0, 16);
  glVertexArrayElementBuffer(meshVao_.id(), 0);
  glDisable(GL_DEPTH_TEST);
  glDepthMask(GL_FALSE);
}

void ObjectCausticsPass::traceRays(GLuint receiverDepth, int iterations) {
  const GLuint textures[] = {frontPosition_.id(), frontNormal_.id(), backPosition_.id(),
                             backNormal_.id(), receiverDepth};
  glBindTextures(POSTFX_OBJECT_UNIT_FRONT_POSITION, 5, textures);
  const GLuint point = pointSampler_.id(), linear = linearSampler_.id();
  const GLuint samplers[] = {point, point, point, point, linear};
  glBindSamplers(POSTFX_OBJECT_UNIT_FRONT_POSITION, 5, samplers);
  glBindImageTexture(POSTFX_IMAGE_OBJECT_LANDINGS, landings_.id(), 0, GL_TRUE, 0, GL_WRITE_ONLY,
                     GL_RGBA32F);
  glUseProgram(trace_.id());
  const GLuint cellGroups = (static_cast<GLuint>(gridSize_) + 7) / 8;
  // object_caustics_trace.comp per ray on its full path (through a glass caster onto a
  // receiver): its cell's front position and normal, the back surface's 2 x 2 positions and
  // normals (8) at the entry, at each of `iterations` probes and at the exit, the receiver depth
  // at the entry, each probe and the landing. Data-dependent: a ray that misses the casters
  // reads one texel, a mirror's skips the back.
  const double fetches = 2.0 + 8.0 * (iterations + 2) + (iterations + 2);
  const std::uint64_t casterBytes = std::uint64_t(gridSize_) * gridSize_ * 16 * 4;
  work::dispatchCompute({"object_caustics.trace",
                         {},
                         {fetches, 0.0, true},
                         {Traffic::readBytes(casterBytes), Traffic::read(receiverDepth),
                          Traffic::write(landings_.id())}},
                        cellGroups, cellGroups, dispersed_ ? 3 : 1);
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
}

void ObjectCausticsPass::drawSplats(GLuint fbo, int mapSize) {
  const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  glClearNamedFramebufferfv(fbo, GL_COLOR, 0, zero);
  work::noteClear("object_caustics.map_clear", std::uint64_t(mapSize) * mapSize * 16);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fbo);
  const float size = static_cast<float>(mapSize);
  glViewportIndexedf(0, 0.0f, 0.0f, size, size);
  glEnablei(GL_BLEND, 0);
  glBlendFuncSeparatei(0, GL_ONE, GL_ONE, GL_ONE, GL_ONE);
  glBlendEquationSeparatei(0, GL_FUNC_ADD, GL_FUNC_ADD);
  glEnable(GL_PROGRAM_POINT_SIZE);
  glBindTextureUnit(POSTFX_OBJECT_UNIT_LANDINGS, landings_.id());
  glBindSampler(POSTFX_OBJECT_UNIT_LANDINGS, pointSampler_.id());
  glBindVertexArray(emptyVao_.id());
  glUseProgram(splat_.id());
  // A dispersed caster needs one ray per colour channel: three instances, the shader drops the
  // extra rays of the others. Without dispersion the draw is the single grid it always was.
  // object_caustics_splat.vert per ray on its full path (it lands, and so do its neighbours):
  // its landing and flux, and the landings of its four neighbours that shape the splat; the
  // fragment stage weighs a Gaussian, no fetches.
  work::drawArrays({"object_caustics.splats",
                    {6.0, 0.0},
                    {},
                    {Traffic::readBytes(std::uint64_t(gridSize_) * gridSize_ * 32)}},
                   GL_POINTS, 0, gridSize_ * gridSize_, dispersed_ ? 3 : 1);
  glDisable(GL_PROGRAM_POINT_SIZE);
}

void ObjectCausticsPass::filterTemporally(const FrameDesc& frame) {
  const ObjectCausticsSettings& s = frame.objectCaustics.settings;
  if (!s.temporalFilter) {
    historyValid_ = false;
    map_ = placement_;
    map_.texture = splatMap_.id();
    return;
  }
  const int out = historyIndex_ ^ 1;
  glNamedFramebufferTexture(temporalFbo_.id(), GL_COLOR_ATTACHMENT0, history_[out].id(), 0);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, temporalFbo_.id());
  glDisablei(GL_BLEND, 0);
  const GLuint textures[] = {splatMap_.id(), history_[historyIndex_].id()};
  glBindTextures(POSTFX_OBJECT_UNIT_CURRENT_MAP, 2, textures);
  const GLuint samplers[] = {pointSampler_.id(), pointSampler_.id()};
  glBindSamplers(POSTFX_OBJECT_UNIT_CURRENT_MAP, 2, samplers);
  glProgramUniform1f(temporal_.id(), kHistoryWeight, historyValid_ ? s.temporalWeight : 0.0f);
  glUseProgram(temporal_.id());
  // object_caustics_temporal.frag per map texel: the 3 x 3 around it (its own read twice) and
  // its history.
  work::drawArrays({"object_caustics.temporal",
                    {},
                    {11.0, 0.0},
                    {Traffic::read(splatMap_.id()), Traffic::read(history_[historyIndex_].id())}},
                   GL_TRIANGLES, 0, 3);
  historyIndex_ = out;
  historyValid_ = true;
  map_ = placement_;
  map_.texture = history_[out].id();
}

void ObjectCausticsPass::composite(const ObjectCausticsTarget& target, GLuint map,
                                   GLuint receiverDepth) {
  const FrameDesc& frame = *target.frame;
  const ValidatedTextures& r = target.rect;
  glNamedFramebufferTexture(compositeFbo_.id(), GL_COLOR_ATTACHMENT0, frame.target.texture, 0);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, compositeFbo_.id());
  glViewportIndexedf(0, static_cast<float>(r.x), static_cast<float>(r.y),
                     static_cast<float>(r.width), static_cast<float>(r.height));
  glEnablei(GL_BLEND, 0);
  glBlendFuncSeparatei(0, GL_ONE, GL_ONE, GL_ONE, GL_ONE);
  glBlendEquationSeparatei(0, GL_FUNC_ADD, GL_FUNC_ADD);
  const GLuint textures[] = {frame.depth.texture, frame.normal.texture, frame.albedo.texture, map,
                             receiverDepth};
  glBindTextures(POSTFX_UNIT_DEPTH, 5, textures);
  const GLuint point = pointSampler_.id(), linear = linearSampler_.id();
  const GLuint samplers[] = {point, point, point, linear, point};
  glBindSamplers(POSTFX_UNIT_DEPTH, 5, samplers);
  glUseProgram(composite_.id());
  // object_caustics_composite.frag on its full path (a lit receiver inside the map): depth,
  // normal, the receiver depth, the map, albedo.
  const double share =
      double(r.width) * r.height / std::max(1.0, double(r.targetWidth) * r.targetHeight);
  work::drawArrays({"object_caustics.composite",
                    {},
                    {5.0, 0.0},
                    {Traffic::readLevel0(frame.depth.texture, share),
                     Traffic::readLevel0(frame.normal.texture, share),
                     Traffic::readLevel0(frame.albedo.texture, share), Traffic::read(map),
                     Traffic::read(receiverDepth)}},
                   GL_TRIANGLES, 0, 3);
}

void ObjectCausticsPass::drawVolume(const ObjectCausticsTarget& target) {
  // composite() left blending additive. The rays are summed in float at the view's size, then
  // added to its rectangle of the target.
  const ValidatedTextures& r = target.rect;
  const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  glClearNamedFramebufferfv(volumeFbo_.id(), GL_COLOR, 0, zero);
  work::noteClear("volume_caustics.clear", std::uint64_t(r.width) * r.height * 16);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, volumeFbo_.id());
  glViewportIndexedf(0, 0.0f, 0.0f, static_cast<float>(r.width), static_cast<float>(r.height));
  glBindTextureUnit(POSTFX_UNIT_DEPTH, target.frame->depth.texture);
  glBindSampler(POSTFX_UNIT_DEPTH, pointSampler_.id());
  glBindTextureUnit(POSTFX_OBJECT_UNIT_LANDINGS, landings_.id());
  glBindSampler(POSTFX_OBJECT_UNIT_LANDINGS, pointSampler_.id());
  glBindVertexArray(emptyVao_.id());
  const GLsizei rays = gridSize_ * gridSize_;
  const GLsizei channels = dispersed_ ? 3 : 1;
  // volume_caustics.vert per vertex on its full path: its ray's segment and power (three
  // texels) and, for a beam, the segments of its four neighbours that shape its cross-section
  // (two each); .frag per fragment (inside the kernel, in front of the surface): the pixel's
  // depth.
  const double share =
      double(r.width) * r.height / std::max(1.0, double(r.targetWidth) * r.targetHeight);
  const TrafficList beamTraffic{Traffic::readBytes(std::uint64_t(rays) * channels * 48),
                                Traffic::readLevel0(target.frame->depth.texture, share)};
  if (volumeMethod_ == VolumeCausticsMethod::Lines) {
    glLineWidth(1.0f);
    glUseProgram(volumeLines_.id());
    work::drawArrays({"volume_caustics.lines", {3.0, 0.0}, {1.0, 0.0}, beamTraffic}, GL_LINES, 0,
                     2 * rays, channels);
  } else {
    glUseProgram(volumeBeams_.id());
    work::drawArrays({"volume_caustics.beams", {11.0, 0.0}, {1.0, 0.0}, beamTraffic}, GL_TRIANGLES,
                     0, 6 * rays, channels);
  }
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, compositeFbo_.id());
  glViewportIndexedf(0, static_cast<float>(r.x), static_cast<float>(r.y),
                     static_cast<float>(r.width), static_cast<float>(r.height));
  glBindTextureUnit(POSTFX_OBJECT_UNIT_VOLUME_LIGHT, volumeLight_.id());
  glBindSampler(POSTFX_OBJECT_UNIT_VOLUME_LIGHT, pointSampler_.id());
  glUseProgram(volumeResolve_.id());
  // volume_caustics_resolve.frag: the pixel's summed light.
  work::drawArrays({"volume_caustics.resolve",
                    {},
                    {1.0, 0.0},
                    {Traffic::readBytes(std::uint64_t(r.width) * r.height * 16)}},
                   GL_TRIANGLES, 0, 3);
}

void ObjectCausticsPass::finishDraws() {
  glNamedFramebufferTexture(compositeFbo_.id(), GL_COLOR_ATTACHMENT0, 0, 0);
}

void ObjectCausticsPass::setDrawState() {
  // Our own conventions for the maps: lower-left origin, depth in [0, 1], nothing clamped,
  // culled, offset or restarted (the host's winding and index streams are not ours to know).
  glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
  glDepthRangeIndexed(0, 0.0, 1.0);
  glDisable(GL_DEPTH_CLAMP);
  glDisable(GL_PRIMITIVE_RESTART);
  glDisable(GL_PRIMITIVE_RESTART_FIXED_INDEX);
  glDisable(GL_POLYGON_OFFSET_FILL);
  glDisable(GL_STENCIL_TEST);
  glDisable(GL_CULL_FACE);
  glDisable(GL_RASTERIZER_DISCARD);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  glDisablei(GL_SCISSOR_TEST, 0);
  glDisablei(GL_BLEND, 0);
  glDisablei(GL_BLEND, 1);
  glColorMaski(0, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glColorMaski(1, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  GLint maxClip = 0;
  glGetIntegerv(GL_MAX_CLIP_DISTANCES, &maxClip);
  for (GLint i = 0; i < maxClip && i < 8; ++i)
    glDisable(static_cast<GLenum>(GL_CLIP_DISTANCE0 + i));
}

void ObjectCausticsPass::drawSun(std::span<const ObjectCausticsTarget> targets) {
  // The maps depend on the sun and the casters only: drawn once, with the first view's block.
  const FrameDesc& frame = *targets[0].frame;
  bindBlock(0);
  const GLuint receiverDepth = frame.objectCaustics.receivers.depth.texture;
  drawCasterMaps(frame, light_);
  traceRays(receiverDepth, frame.objectCaustics.settings.iterations);
  drawSplats(splatFbo_.id(), mapSize_);
  glBindVertexArray(emptyVao_.id());
  glViewportIndexedf(0, 0.0f, 0.0f, static_cast<float>(mapSize_), static_cast<float>(mapSize_));
  filterTemporally(frame);
  for (std::size_t v = 0; v < targets.size(); ++v) {
    bindBlock(static_cast<int>(v * slotsPerView_));
    composite(targets[v], map_.texture, receiverDepth);
    if (volume_) drawVolume(targets[v]);
  }
}

void ObjectCausticsPass::drawLight(std::span<const ObjectCausticsTarget> targets, int k) {
  const FrameDesc& frame = *targets[0].frame;
  const ObjectLightFrame& view = lights_[static_cast<std::size_t>(k)];
  bindBlock(k + 1);
  const GLuint receiverDepth = frame.objectCaustics.lights[view.light].receivers.depth.texture;
  // The same caster maps, trace and splats as the sun's, through the light's perspective view
  // (its block); no temporal filter.
  drawCasterMaps(frame, view);
  traceRays(receiverDepth, frame.objectCaustics.settings.iterations);
  drawSplats(lightFbo_.id(), lightMapSize_);
  glBindVertexArray(emptyVao_.id());
  for (std::size_t v = 0; v < targets.size(); ++v) {
    bindBlock(static_cast<int>(v * slotsPerView_) + k + 1);
    composite(targets[v], lightMap_.id(), receiverDepth);
    if (volume_) drawVolume(targets[v]);
  }
  lightMapClip_ = localLightMapClip(view);
}

}  // namespace postfx::detail
