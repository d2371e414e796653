// Any host GL state gives the same image: each piece of state that can change what a
// draw writes is set, one at a time, to a hostile value before dispatch(); the light added to
// the target (and the raw caustic output) must be bit-identical to the clean run, and every
// piece of state must read back as the host set it. The list below is written from the GL 4.5
// specification's per-fragment and rasterization state, not from the plugin's guard, so an
// omission in the guard shows up here as a changed image or a changed state.
#include <gtest/gtest.h>
#include <postfx/testing.h>

#include <cstdio>
#include <cstring>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "gl_fixture.h"
#include "postfx_gl_snapshot.h"
#include "postfx_host_state.h"
#include "postfx_object_caustics_util.h"

namespace {

using namespace postfxtest;
using postfx::Result;

struct Hostile {
  std::string name;
  std::function<void()> set, reset;
};

void enable(GLenum cap, bool on) {
  if (on) {
    glEnable(cap);
  } else {
    glDisable(cap);
  }
}

Hostile capability(const char* name, GLenum cap, bool hostileOn = true) {
  return {name, [cap, hostileOn] { enable(cap, hostileOn); },
          [cap, hostileOn] { enable(cap, !hostileOn); }};
}

std::vector<Hostile> hostileStates() {
  std::vector<Hostile> list = {
      {"logic op XOR",
       [] {
         glEnable(GL_COLOR_LOGIC_OP);
         glLogicOp(GL_XOR);
       },
       [] {
         glDisable(GL_COLOR_LOGIC_OP);
         glLogicOp(GL_COPY);
       }},
      {"logic op SET",
       [] {
         glEnable(GL_COLOR_LOGIC_OP);
         glLogicOp(GL_SET);
       },
       [] {
         glDisable(GL_COLOR_LOGIC_OP);
         glLogicOp(GL_COPY);
       }},
      capability("multisample off", GL_MULTISAMPLE, false),
      {"sample coverage 0 inverted",
       [] {
         glEnable(GL_SAMPLE_COVERAGE);
         glSampleCoverage(0.0f, GL_FALSE);
       },
       [] {
         glDisable(GL_SAMPLE_COVERAGE);
         glSampleCoverage(1.0f, GL_FALSE);
       }},
      capability("alpha to coverage", GL_SAMPLE_ALPHA_TO_COVERAGE),
      capability("alpha to one", GL_SAMPLE_ALPHA_TO_ONE),
      {"sample mask 0",
       [] {
         glEnable(GL_SAMPLE_MASK);
         glSampleMaski(0, 0u);
       },
       [] {
         glDisable(GL_SAMPLE_MASK);
         glSampleMaski(0, ~0u);
       }},
      {"sample shading",
       [] {
         glEnable(GL_SAMPLE_SHADING);
         glMinSampleShading(1.0f);
       },
       [] {
         glDisable(GL_SAMPLE_SHADING);
         glMinSampleShading(0.0f);
       }},
      capability("rasterizer discard", GL_RASTERIZER_DISCARD),
      {"polygon mode line", [] { glPolygonMode(GL_FRONT_AND_BACK, GL_LINE); },
       [] { glPolygonMode(GL_FRONT_AND_BACK, GL_FILL); }},
      {"polygon mode point", [] { glPolygonMode(GL_FRONT_AND_BACK, GL_POINT); },
       [] { glPolygonMode(GL_FRONT_AND_BACK, GL_FILL); }},
      {"polygon offset fill/line/point",
       [] {
         glEnable(GL_POLYGON_OFFSET_FILL);
         glEnable(GL_POLYGON_OFFSET_LINE);
         glEnable(GL_POLYGON_OFFSET_POINT);
         glPolygonOffset(1e4f, 1e6f);
       },
       [] {
         glDisable(GL_POLYGON_OFFSET_FILL);
         glDisable(GL_POLYGON_OFFSET_LINE);
         glDisable(GL_POLYGON_OFFSET_POINT);
         glPolygonOffset(0.0f, 0.0f);
       }},
      capability("depth clamp", GL_DEPTH_CLAMP),
      capability("framebuffer sRGB", GL_FRAMEBUFFER_SRGB),
      {"primitive restart at index 0",
       [] {
         glEnable(GL_PRIMITIVE_RESTART);
         glPrimitiveRestartIndex(0);
       },
       [] {
         glDisable(GL_PRIMITIVE_RESTART);
         glPrimitiveRestartIndex(0);
       }},
      capability("primitive restart fixed index", GL_PRIMITIVE_RESTART_FIXED_INDEX),
      {"provoking vertex first", [] { glProvokingVertex(GL_FIRST_VERTEX_CONVENTION); },
       [] { glProvokingVertex(GL_LAST_VERTEX_CONVENTION); }},
      {"blend colour with constant-colour blending everywhere",
       [] {
         glBlendColor(0.5f, 0.25f, 2.0f, -1.0f);
         glEnable(GL_BLEND);
         glBlendFunc(GL_CONSTANT_COLOR, GL_ONE_MINUS_CONSTANT_ALPHA);
       },
       [] {
         glBlendColor(0.0f, 0.0f, 0.0f, 0.0f);
         glDisable(GL_BLEND);
         glBlendFunc(GL_ONE, GL_ZERO);
       }},
      {"stencil test NEVER",
       [] {
         glEnable(GL_STENCIL_TEST);
         glStencilFuncSeparate(GL_FRONT_AND_BACK, GL_NEVER, 1, 0xff);
         glStencilOp(GL_ZERO, GL_ZERO, GL_ZERO);
       },
       [] {
         glDisable(GL_STENCIL_TEST);
         glStencilFuncSeparate(GL_FRONT_AND_BACK, GL_ALWAYS, 0, 0xff);
         glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
       }},
      capability("dither off", GL_DITHER, false),
      {"depth test NEVER, no depth writes",
       [] {
         glEnable(GL_DEPTH_TEST);
         glDepthFunc(GL_NEVER);
         glDepthMask(GL_FALSE);
       },
       [] {
         glDisable(GL_DEPTH_TEST);
         glDepthFunc(GL_LESS);
         glDepthMask(GL_TRUE);
       }},
      {"depth range [1, 0]", [] { glDepthRangeIndexed(0, 1.0, 0.0); },
       [] { glDepthRangeIndexed(0, 0.0, 1.0); }},
      {"clip control upper-left [0,1]", [] { glClipControl(GL_UPPER_LEFT, GL_ZERO_TO_ONE); },
       [] { glClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE); }},
      {"cull front and back, clockwise",
       [] {
         glEnable(GL_CULL_FACE);
         glCullFace(GL_FRONT_AND_BACK);
         glFrontFace(GL_CW);
       },
       [] {
         glDisable(GL_CULL_FACE);
         glCullFace(GL_BACK);
         glFrontFace(GL_CCW);
       }},
      capability("line smooth", GL_LINE_SMOOTH),
      capability("polygon smooth", GL_POLYGON_SMOOTH),
      {"point size 63, program point size off",
       [] {
         glPointSize(63.0f);
         glDisable(GL_PROGRAM_POINT_SIZE);
       },
       [] { glPointSize(1.0f); }},
      capability("program point size", GL_PROGRAM_POINT_SIZE),
      {"point sprite origin lower-left",
       [] { glPointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, GL_LOWER_LEFT); },
       [] { glPointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, GL_UPPER_LEFT); }},
  };
  for (GLuint i = 0; i < 8; ++i) {
    const GLenum cap = GL_CLIP_DISTANCE0 + i;
    list.push_back(capability(("clip distance " + std::to_string(i)).c_str(), cap));
    list.push_back({"colour mask off on draw buffer " + std::to_string(i),
                    [i] { glColorMaski(i, GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE); },
                    [i] { glColorMaski(i, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE); }});
    list.push_back({"blend MIN with zero factors on draw buffer " + std::to_string(i),
                    [i] {
                      glEnablei(GL_BLEND, i);
                      glBlendFuncSeparatei(i, GL_ZERO, GL_SRC_COLOR, GL_ZERO, GL_ZERO);
                      glBlendEquationSeparatei(i, GL_MIN, GL_FUNC_REVERSE_SUBTRACT);
                    },
                    [i] {
                      glDisablei(GL_BLEND, i);
                      glBlendFuncSeparatei(i, GL_ONE, GL_ZERO, GL_ONE, GL_ZERO);
                      glBlendEquationSeparatei(i, GL_FUNC_ADD, GL_FUNC_ADD);
                    }});
  }
  for (GLuint i = 0; i < 16; ++i) {
    list.push_back({"scissor 1x1 on viewport " + std::to_string(i),
                    [i] {
                      glEnablei(GL_SCISSOR_TEST, i);
                      glScissorIndexed(i, 0, 0, 1, 1);
                    },
                    [i] {
                      glDisablei(GL_SCISSOR_TEST, i);
                      glScissorIndexed(i, 0, 0, 1, 1);
                    }});
    list.push_back({"viewport " + std::to_string(i) + " 1x1 at (2, 3)",
                    [i] { glViewportIndexedf(i, 2.0f, 3.0f, 1.0f, 1.0f); },
                    [i] { glViewportIndexedf(i, 0.0f, 0.0f, 1.0f, 1.0f); }});
  }
  // A host's texture of every target (1D to cube-map array, multisample, rectangle, buffer) on
  // every unit the plugin uses and beyond, a sampler on each, image units bound, and the rest
  // of postfx_host_state.h's state: glBindTextureUnit(unit, 0) clears all of a unit's targets.
  auto host = std::make_shared<HostState>();
  list.push_back({"every texture target on every unit (postfx_host_state.h)",
                  [host] {
                    host->set();
                    // Its pack state is left at the defaults: this test reads the output back
                    // inside the hostile state, and the plugin reads nothing back.
                    glPixelStorei(GL_PACK_ALIGNMENT, 4);
                    glPixelStorei(GL_PACK_ROW_LENGTH, 0);
                  },
                  [host] { host->reset(); }});
  // And all of them at once.
  std::vector<Hostile> each = list;
  list.push_back({"every state above at once",
                  [each] {
                    for (const Hostile& h : each) h.set();
                  },
                  [each] {
                    for (const Hostile& h : each) h.reset();
                  }});
  return list;
}

// What one context adds for one frame: the target's bits and, if any, the raw output's.
struct Output {
  std::vector<glm::vec4> target;
  std::vector<float> raw;
  bool operator==(const Output& o) const {
    return target.size() == o.target.size() && raw.size() == o.raw.size() &&
           std::memcmp(target.data(), o.target.data(), target.size() * sizeof(glm::vec4)) == 0 &&
           (raw.empty() || std::memcmp(raw.data(), o.raw.data(), raw.size() * sizeof(float)) == 0);
  }
};

struct Case {
  const char* name;
  postfx::Context* fx;
  const Scene* scene;
  postfx::FrameDesc frame;
};

Output run(const Case& c) {
  c.scene->clearTarget(glm::vec4(0.125f, 0.25f, 0.5f, 1.0f));
  EXPECT_EQ(postfx::dispatch(*c.fx, c.frame), Result::Ok) << postfx::lastError(c.fx);
  Output out;
  const int w = c.scene->spec().width, h = c.scene->spec().height;
  out.target = readRgba(c.scene->target, w, h);
  if (const GLuint raw = postfx::testing::rawCausticTexture(*c.fx)) out.raw = readRed(raw, w, h);
  return out;
}

// Total absolute difference from the marker: that the context added light at all.
double added(const Output& o) {
  double sum = 0.0;
  for (const glm::vec4& v : o.target)
    sum += double(std::abs(v.r - 0.125f) + std::abs(v.g - 0.25f) + std::abs(v.b - 0.5f));
  return sum;
}

class PostfxHostileStateTest : public testsupport::GlTest {};

TEST_F(PostfxHostileStateTest, AnyHostStateGivesTheSameImageAndIsRestored) {
  // Seabed caustics + god rays at half resolution (raw output, dispersion, benchmark floor).
  Scene seabed(SceneSpec{});
  const GLuint water = makeWaterTexture(32, 3, 0.02);
  auto full = makeContext(postfx::Feature::Caustics | postfx::Feature::GodRays |
                          postfx::testing::RawCausticOutput | postfx::Feature::Dispersion |
                          postfx::testing::BenchmarkFloor);
  postfx::FrameDesc seabedFrame = makeFrame(seabed, water, 3);
  // The physical model (compute, instanced strips, points into its own framebuffer) with god
  // rays at full resolution.
  auto physical = makeContext(postfx::Feature::Caustics | postfx::Feature::GodRays |
                              postfx::Feature::WavefrontAreaRatio);
  postfx::FrameDesc physicalFrame = makeFrame(seabed, water, 3);
  physicalFrame.caustics.model = postfx::CausticsModel::WavefrontAreaRatio;
  physicalFrame.caustics.gridResolution = 64;
  physicalFrame.godRays.resolution = postfx::GodRayResolution::Full;
  // Object caustics: depth-tested caster maps, point splats, composite.
  ObjectHost host(sunAt(20.0, 30.0));
  const GlMesh mesh = makeSphereMesh(1.0, 32, 16);
  const postfx::CasterMesh caster =
      mesh.caster(translation({0.2, 1.5, 0.1}), postfx::CasterMaterial{});
  auto objects = makeObjectContext();
  postfx::ObjectCausticsSettings settings;
  settings.gridSize = 128;
  settings.mapSize = 256;
  const postfx::FrameDesc objectFrame = host.frame(&caster, 1, settings);
  // Their volume caustics under the water: instanced quads (beams) and GL lines into a float
  // texture, then added to the target.
  auto volume = makeObjectContext(postfx::Feature::VolumeCaustics);
  postfx::FrameDesc beamsFrame = host.frame(&caster, 1, settings);
  beamsFrame.water.level = 10.0;
  postfx::FrameDesc linesFrame = beamsFrame;
  linesFrame.objectCaustics.settings.volume.method = postfx::VolumeCausticsMethod::Lines;

  // Local water with no region: its lookup unit is unbound (the unit a host's cube map was lost
  // from).
  auto local = makeContext(postfx::Feature::Caustics | postfx::Feature::LocalWater);
  const postfx::FrameDesc localFrame = makeFrame(seabed, water, 3);

  const Case cases[] = {{"seabed + god rays (half)", full.get(), &seabed, seabedFrame},
                        {"local water, no region", local.get(), &seabed, localFrame},
                        {"physical + god rays (full)", physical.get(), &seabed, physicalFrame},
                        {"object caustics", objects.get(), &host.scene, objectFrame},
                        {"volume caustics (beams)", volume.get(), &host.scene, beamsFrame},
                        {"volume caustics (lines)", volume.get(), &host.scene, linesFrame}};
  std::vector<Output> clean;
  for (const Case& c : cases) {
    clean.push_back(run(c));
    // The comparison means something only if the clean run is repeatable and adds light.
    ASSERT_TRUE(run(c) == clean.back()) << c.name << ": two clean runs differ";
    EXPECT_GT(added(clean.back()), 1.0) << c.name << " added no light";
  }
  expectNoGlErrors("clean runs");

  int states = 0;
  for (const Hostile& h : hostileStates()) {
    ++states;
    for (size_t k = 0; k < std::size(cases); ++k) {
      const Case& c = cases[k];
      SCOPED_TRACE(h.name + " / " + c.name);
      h.set();
      const GlSnapshot before = snapshotGlState();
      const Output out = run(c);
      const GlSnapshot after = snapshotGlState();
      h.reset();
      for (const auto& [name, value] : before)
        EXPECT_EQ(value, after.at(name)) << "GL state '" << name << "' not restored";
      EXPECT_TRUE(out == clean[k]) << "the output differs from the clean run's";
      expectNoGlErrors(h.name.c_str());
    }
  }
  std::printf("hostile states: %d, each in %zu contexts: output bit-identical, state restored\n",
              states, std::size(cases));
  glDeleteTextures(1, &water);
}

// Transform feedback active while dispatch() is called: refused before anything is drawn
// (GL would refuse the plugin's glUseProgram). Paused, it is no obstacle.
TEST_F(PostfxHostileStateTest, ActiveTransformFeedbackIsRefused) {
  Scene scene(SceneSpec{});
  const GLuint water = makeWaterTexture(32, 3, 0.02);
  auto fx = makeContext(postfx::Feature::Caustics | postfx::Feature::GodRays);
  const postfx::FrameDesc frame = makeFrame(scene, water, 3);
  const char* vs =
      "#version 450 core\nout float captured;\nvoid main() { captured = 1.0; gl_Position = "
      "vec4(0.0); }\n";
  const GLuint shader = glCreateShader(GL_VERTEX_SHADER);
  glShaderSource(shader, 1, &vs, nullptr);
  glCompileShader(shader);
  const GLuint program = glCreateProgram();
  glAttachShader(program, shader);
  const char* varying = "captured";
  glTransformFeedbackVaryings(program, 1, &varying, GL_INTERLEAVED_ATTRIBS);
  glLinkProgram(program);
  GLuint buffer = 0, feedback = 0;
  glCreateBuffers(1, &buffer);
  glNamedBufferStorage(buffer, 1024, nullptr, 0);
  glCreateTransformFeedbacks(1, &feedback);
  glTransformFeedbackBufferBase(feedback, 0, buffer);
  glBindTransformFeedback(GL_TRANSFORM_FEEDBACK, feedback);
  glUseProgram(program);
  glBeginTransformFeedback(GL_POINTS);

  const glm::vec4 marker(0.125f, 0.25f, 0.5f, 1.0f);
  scene.clearTarget(marker);
  const GlSnapshot before = snapshotGlState();
  EXPECT_EQ(postfx::dispatch(*fx, frame), Result::InvalidArgument);
  EXPECT_NE(std::string(postfx::lastError(fx.get())).find("transform feedback"), std::string::npos)
      << postfx::lastError(fx.get());
  for (const auto& [name, value] : before) EXPECT_EQ(value, snapshotGlState().at(name)) << name;
  for (const glm::vec4& v : readRgba(scene.target, scene.spec().width, scene.spec().height))
    ASSERT_EQ(v, marker) << "something was drawn";

  glPauseTransformFeedback();
  EXPECT_EQ(postfx::dispatch(*fx, frame), Result::Ok) << postfx::lastError(fx.get());
  glResumeTransformFeedback();
  glEndTransformFeedback();
  glUseProgram(0);
  glBindTransformFeedback(GL_TRANSFORM_FEEDBACK, 0);
  glDeleteTransformFeedbacks(1, &feedback);
  glDeleteBuffers(1, &buffer);
  glDeleteProgram(program);
  glDeleteShader(shader);
  glDeleteTextures(1, &water);
}

// Conditional rendering cannot be queried in GL 4.5, so dispatch() cannot refuse it; postfx.h
// says so. What a host gets: inside a conditional render whose query passed no samples, the
// call returns Ok, adds nothing, and leaves the state as it was.
TEST_F(PostfxHostileStateTest, InsideAFailedConditionalRenderNothingIsAdded) {
  Scene scene(SceneSpec{});
  const GLuint water = makeWaterTexture(32, 3, 0.02);
  auto fx = makeContext(postfx::Feature::Caustics | postfx::Feature::GodRays);
  const postfx::FrameDesc frame = makeFrame(scene, water, 3);
  GLuint query = 0;
  glCreateQueries(GL_ANY_SAMPLES_PASSED, 1, &query);
  glBeginQuery(GL_ANY_SAMPLES_PASSED, query);  // nothing drawn: no sample passes
  glEndQuery(GL_ANY_SAMPLES_PASSED);
  const glm::vec4 marker(0.125f, 0.25f, 0.5f, 1.0f);
  scene.clearTarget(marker);
  glBeginConditionalRender(query, GL_QUERY_WAIT);
  const GlSnapshot before = snapshotGlState();
  EXPECT_EQ(postfx::dispatch(*fx, frame), Result::Ok) << postfx::lastError(fx.get());
  for (const auto& [name, value] : before) EXPECT_EQ(value, snapshotGlState().at(name)) << name;
  glEndConditionalRender();
  for (const glm::vec4& v : readRgba(scene.target, scene.spec().width, scene.spec().height))
    ASSERT_EQ(v, marker) << "the host's failed query discards the plugin's draws";
  // Outside it, the same frame adds light (the test can tell).
  EXPECT_EQ(postfx::dispatch(*fx, frame), Result::Ok);
  int changed = 0;
  for (const glm::vec4& v : readRgba(scene.target, scene.spec().width, scene.spec().height))
    changed += v != marker ? 1 : 0;
  EXPECT_GT(changed, 100);
  glDeleteQueries(1, &query);
  glDeleteTextures(1, &water);
}

}  // namespace
