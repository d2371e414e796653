#include "cpu_calibration.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <vector>

#include "shader_statistics.h"

namespace ocean {
namespace {

constexpr int kWidth = 1024, kHeight = 1024;  // the microbenchmarks' target
constexpr int kRuns = 7;  // the first two warm up (page faults, the thread pool): not counted

const char* kFullScreen = R"(#version 450 core
void main() {
  vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);
  gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
})";
// One triangle of half a pixel at every pixel of the target.
const char* kTinyTriangles = R"(#version 450 core
layout(location = 0) uniform ivec2 size;
void main() {
  int t = gl_VertexID / 3, corner = gl_VertexID % 3;
  vec2 at = vec2(t % size.x, t / size.x) + vec2(corner == 1 ? 1.0 : 0.0, corner == 2 ? 1.0 : 0.0);
  gl_Position = vec4(at / vec2(size) * 2.0 - 1.0, 0.0, 1.0);
})";
const char* kPoints = R"(#version 450 core
void main() {
  gl_Position = vec4(float(gl_VertexID) * 1e-9, 0.0, 0.0, 1.0);
  gl_PointSize = 1.0;
})";
const char* kNoop = R"(#version 450 core
layout(location = 0) out vec4 color;
void main() { color = vec4(gl_FragCoord.xy * 1e-4, 0.0, 1.0); })";
const char* kArithmetic = R"(#version 450 core
layout(location = 0) uniform int count;
layout(location = 1) uniform float k;
layout(location = 0) out vec4 color;
void main() {
  vec4 v = gl_FragCoord.xyxy * 1e-3;
  for (int i = 0; i < count; ++i) v = fma(v, v, vec4(k));
  color = v;
})";
const char* kTranscendental = R"(#version 450 core
layout(location = 0) uniform int count;
layout(location = 0) out vec4 color;
void main() {
  vec4 v = gl_FragCoord.xyxy * 1e-3 + 1.0;
  for (int i = 0; i < count; ++i) v = exp2(log2(v) * 0.999);
  color = v;
})";
const char* kDivision = R"(#version 450 core
layout(location = 0) uniform int count;
layout(location = 0) out vec4 color;
void main() {
  vec4 v = gl_FragCoord.xyxy * 1e-3 + 1.0;
  for (int i = 0; i < count; ++i) v = sqrt(v) / (v + 0.5);
  color = v;
})";
// The plugin's lookups: a layer of a mipmapped RGBA16F array at a level of each pixel's own.
const char* kFetches = R"(#version 450 core
layout(location = 0) uniform int count;
layout(binding = 0) uniform sampler2DArray image;
layout(location = 0) out vec4 color;
void main() {
  vec2 uv = gl_FragCoord.xy * (1.0 / 512.0);
  float lod = fract(gl_FragCoord.x * 0.37 + gl_FragCoord.y * 0.11) * 3.0;
  vec4 sum = vec4(0.0);
  for (int i = 0; i < count; ++i)
    sum += textureLod(image, vec3(uv + vec2(float(i) * 0.013, 0.0), float(i & 3)), lod);
  color = sum;
})";
// mode 0: nothing; 1: four atomic adds at the 2 x 2 texels (rows of 512) around where the
// invocation's point of a 512-wide grid lands, each a pseudo-random few texels away, as the
// plugin's fields gather the light of a grid; 2: a copy of 16 uints (64 bytes) from the second
// buffer.
const char* kCompute = R"(#version 450 core
layout(local_size_x = 64) in;
layout(std430, binding = 0) buffer Counters { uint counters[]; };
layout(std430, binding = 1) readonly buffer Source { uint source[]; };
layout(location = 0) uniform int mode;
layout(location = 1) uniform uint mask;
void main() {
  uint i = gl_GlobalInvocationID.x;
  if (mode == 1) {
    uint at = (i + (((i * 2654435761u) >> 28) & 7u)) & mask;
    atomicAdd(counters[at], 1u);
    atomicAdd(counters[(at + 1u) & mask], 1u);
    atomicAdd(counters[(at + 512u) & mask], 1u);
    atomicAdd(counters[(at + 513u) & mask], 1u);
  }
  else if (mode == 2)
    for (uint k = 0u; k < 16u; ++k) counters[(16u * i + k) & mask] = source[(16u * i + k) & mask];
  else if (i == 0xffffffffu) counters[0] = 1u;
})";

GLuint compile(GLenum type, const char* source) {
  const GLuint shader = glCreateShader(type);
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  return shader;
}

// A linked program of the given stages (0 on failure) and what the driver compiled of it.
struct Program {
  GLuint id = 0;
  cost::ProgramStatistics statistics;
};
Program link(std::initializer_list<std::pair<GLenum, const char*>> stages) {
  cost::ShaderDumpCapture capture;
  Program p;
  p.id = glCreateProgram();
  std::vector<GLuint> shaders;
  for (const auto& [type, source] : stages) {
    shaders.push_back(compile(type, source));
    glAttachShader(p.id, shaders.back());
  }
  glLinkProgram(p.id);
  for (GLuint s : shaders) glDeleteShader(s);
  GLint ok = GL_FALSE;
  glGetProgramiv(p.id, GL_LINK_STATUS, &ok);
  const auto parsed = cost::parseNirDump(capture.text());
  const auto it = parsed.find(p.id);
  if (it != parsed.end()) p.statistics = it->second;
  if (ok != GL_TRUE) {
    glDeleteProgram(p.id);
    p.id = 0;
  }
  return p;
}

struct Measured {
  double seconds = 0.0;  // median of kRuns
  GLuint64 fragments = 0, primitives = 0, samples = 0;
};

Measured measure(const std::function<void()>& work) {
  GLuint queries[3];
  glGenQueries(3, queries);
  std::vector<double> times;
  Measured m;
  for (int run = 0; run < kRuns; ++run) {
    glFinish();
    glBeginQuery(GL_FRAGMENT_SHADER_INVOCATIONS_ARB, queries[0]);
    glBeginQuery(GL_CLIPPING_OUTPUT_PRIMITIVES_ARB, queries[1]);
    glBeginQuery(GL_SAMPLES_PASSED, queries[2]);
    // The CPU's own clock: llvmpipe's GL_TIME_ELAPSED around a lone draw here read 1/200 of it.
    const auto start = std::chrono::steady_clock::now();
    work();
    glFinish();
    const auto end = std::chrono::steady_clock::now();
    glEndQuery(GL_SAMPLES_PASSED);
    glEndQuery(GL_CLIPPING_OUTPUT_PRIMITIVES_ARB);
    glEndQuery(GL_FRAGMENT_SHADER_INVOCATIONS_ARB);
    glGetQueryObjectui64v(queries[0], GL_QUERY_RESULT, &m.fragments);
    glGetQueryObjectui64v(queries[1], GL_QUERY_RESULT, &m.primitives);
    glGetQueryObjectui64v(queries[2], GL_QUERY_RESULT, &m.samples);
    times.push_back(std::chrono::duration<double>(end - start).count());
  }
  glDeleteQueries(3, queries);
  times.erase(times.begin(), times.begin() + 2);
  std::sort(times.begin(), times.end());
  m.seconds = times[times.size() / 2];
  return m;
}

GLuint target(GLenum format) {
  GLuint texture = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &texture);
  glTextureStorage2D(texture, 1, format, kWidth, kHeight);
  return texture;
}

}  // namespace

bool calibrateCpu(cost::CpuClass& cpu, std::string& error) {
  const Program noop = link({{GL_VERTEX_SHADER, kFullScreen}, {GL_FRAGMENT_SHADER, kNoop}});
  const Program arithmetic =
      link({{GL_VERTEX_SHADER, kFullScreen}, {GL_FRAGMENT_SHADER, kArithmetic}});
  const Program fetches = link({{GL_VERTEX_SHADER, kFullScreen}, {GL_FRAGMENT_SHADER, kFetches}});
  const Program transcendental =
      link({{GL_VERTEX_SHADER, kFullScreen}, {GL_FRAGMENT_SHADER, kTranscendental}});
  const Program division = link({{GL_VERTEX_SHADER, kFullScreen}, {GL_FRAGMENT_SHADER, kDivision}});
  const Program tiny = link({{GL_VERTEX_SHADER, kTinyTriangles}, {GL_FRAGMENT_SHADER, kNoop}});
  const Program points = link({{GL_VERTEX_SHADER, kPoints}, {GL_FRAGMENT_SHADER, kNoop}});
  const Program compute = link({{GL_COMPUTE_SHADER, kCompute}});
  const Program all[] = {noop,     arithmetic, fetches, transcendental,
                         division, tiny,       points,  compute};
  auto release = [&] {
    for (const Program& p : all) glDeleteProgram(p.id);
  };
  for (const Program& p : all)
    if (p.id == 0) {
      release();
      error = "calibration: a microbenchmark's program did not link";
      return false;
    }
  if (!arithmetic.statistics.fragment.present) {
    release();
    error = "calibration: the driver printed no NIR (Mesa's llvmpipe is needed)";
    return false;
  }

  const GLuint half = target(GL_RGBA16F), full = target(GL_RGBA32F);
  GLuint framebuffer = 0, vertexArray = 0, image = 0, buffer = 0;
  glCreateFramebuffers(1, &framebuffer);
  glCreateVertexArrays(1, &vertexArray);
  glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &image);
  glTextureStorage3D(image, 10, GL_RGBA16F, 512, 512, 4);
  glTextureParameteri(image, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  constexpr GLuint kFarEntries = 1u << 24;  // 64 MiB of uints
  GLuint source = 0;
  glCreateBuffers(1, &buffer);
  glNamedBufferStorage(buffer, GLsizeiptr(kFarEntries) * 4, nullptr, GL_DYNAMIC_STORAGE_BIT);
  glCreateBuffers(1, &source);
  glNamedBufferStorage(source, GLsizeiptr(kFarEntries) * 4, nullptr, GL_DYNAMIC_STORAGE_BIT);
  // Touched once before any run: their pages are the driver's from the start.
  const GLuint zeroWord = 0;
  glClearNamedBufferData(buffer, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zeroWord);
  glClearNamedBufferData(source, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zeroWord);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer);
  glViewport(0, 0, kWidth, kHeight);
  glBindVertexArray(vertexArray);
  glDisable(GL_BLEND);
  glDisable(GL_DEPTH_TEST);
  auto into = [&](GLuint texture) {
    glNamedFramebufferTexture(framebuffer, GL_COLOR_ATTACHMENT0, texture, 0);
  };

  // A fragment lane, writing RGBA16F, of an (almost) empty shader.
  into(half);
  glUseProgram(noop.id);
  const Measured base = measure([] { glDrawArrays(GL_TRIANGLES, 0, 3); });
  const double lanes = double(base.fragments);
  const double baseAlu = noop.statistics.fragment.alu;
  cpu.fragmentLane = base.seconds / lanes;

  // Arithmetic: 64 vec4 FMAs more per lane.
  constexpr int kLoops = 64;
  glUseProgram(arithmetic.id);
  glUniform1i(0, kLoops);
  glUniform1f(1, 0.5f);
  const Measured alu = measure([] { glDrawArrays(GL_TRIANGLES, 0, 3); });
  const double aluOps = arithmetic.statistics.fragment.perInvocation(0.0, 0.0) - baseAlu +
                        arithmetic.statistics.fragment.loopAlu * (kLoops - 1);
  cpu.aluOp = std::max(alu.seconds - base.seconds, 0.0) / (lanes * std::max(aluOps, 1.0));

  // Special functions, 32 more per vec4 component and lane, their cost beyond an arithmetic
  // op's: exp2 and log2; a division and a square root.
  auto special = [&](const Program& program, bool transcendentals) {
    glUseProgram(program.id);
    glUniform1i(0, kLoops / 2);
    const Measured m = measure([] { glDrawArrays(GL_TRIANGLES, 0, 3); });
    const cost::StageStatistics& s = program.statistics.fragment;
    const double count = transcendentals ? s.transcendental + s.loopTranscendental * (kLoops / 2)
                                         : s.division + s.loopDivision * (kLoops / 2);
    const double ops = s.alu + s.loopAlu * (kLoops / 2) - baseAlu;
    return std::max(m.seconds - base.seconds - lanes * ops * cpu.aluOp, 0.0) /
           (lanes * std::max(count, 1.0));
  };
  cpu.transcendental = special(transcendental, true);
  cpu.division = special(division, false);

  // Texture fetches: 16 trilinear RGBA16F array lookups more per lane at a level of its own
  // (their loop's arithmetic aside).
  constexpr int kFetches = 16;
  glUseProgram(fetches.id);
  glUniform1i(0, kFetches);
  glBindTextureUnit(0, image);
  const Measured fetch = measure([] { glDrawArrays(GL_TRIANGLES, 0, 3); });
  const double fetchAlu = fetches.statistics.fragment.perInvocation(kFetches, 0.0) - baseAlu;
  cpu.fetch = std::max(fetch.seconds - base.seconds - lanes * fetchAlu * cpu.aluOp, 0.0) /
              (lanes * kFetches);

  // Blending, per byte of an RGBA32F sample, beyond writing it.
  into(full);
  glUseProgram(noop.id);
  const Measured written = measure([] { glDrawArrays(GL_TRIANGLES, 0, 3); });
  glEnablei(GL_BLEND, 0);
  glBlendFunci(0, GL_ONE, GL_ONE);
  const Measured blended = measure([] { glDrawArrays(GL_TRIANGLES, 0, 3); });
  glDisablei(GL_BLEND, 0);
  cpu.blendedByte =
      std::max(blended.seconds - written.seconds, 0.0) / (double(blended.samples) * 16.0);

  // Primitives: a half-pixel triangle at every pixel (their lanes at the lane's cost).
  into(half);
  glUseProgram(tiny.id);
  glUniform2i(0, kWidth, kHeight);
  const Measured triangles = measure([] { glDrawArrays(GL_TRIANGLES, 0, 3 * kWidth * kHeight); });
  cpu.primitive =
      std::max(triangles.seconds - double(triangles.fragments) * cpu.fragmentLane, 0.0) /
      double(std::max<GLuint64>(triangles.primitives, 1));

  // Vertices, none rasterised.
  constexpr int kVertices = 1 << 21;
  glUseProgram(points.id);
  glEnable(GL_RASTERIZER_DISCARD);
  const Measured vertices = measure([] { glDrawArrays(GL_POINTS, 0, kVertices); });
  glDisable(GL_RASTERIZER_DISCARD);
  cpu.vertex = vertices.seconds / kVertices;

  // Draw calls: 256 one-triangle draws against one.
  glUseProgram(tiny.id);
  glUniform2i(0, kWidth, kHeight);
  const Measured one = measure([] { glDrawArrays(GL_TRIANGLES, 0, 3); });
  const Measured many = measure([] {
    for (int i = 0; i < 256; ++i) glDrawArrays(GL_TRIANGLES, 3 * i, 3);
  });
  cpu.call = std::max(many.seconds - one.seconds, 0.0) / 255.0;

  // Compute invocations; four atomic adds each, into 4 MiB (the size of the plugin's
  // accumulators, where llvmpipe's two threads seldom meet on a cache line); 64 bytes copied
  // each.
  constexpr GLuint kGroups = 1 << 15;  // 2M invocations
  glUseProgram(compute.id);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, buffer);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, source);
  auto dispatch = [&](int mode, GLuint mask) {
    glUniform1i(0, mode);
    glUniform1ui(1, mask);
    return measure([] { glDispatchCompute(kGroups, 1, 1); });
  };
  const Measured invocations = dispatch(0, 0);
  const Measured atomics = dispatch(1, (1u << 20) - 1);
  const Measured copied = dispatch(2, kFarEntries - 1);
  const double count = double(kGroups) * 64.0;
  cpu.computeInvocation = invocations.seconds / count;
  cpu.atomic = std::max(atomics.seconds - invocations.seconds, 0.0) / (4.0 * count);
  cpu.bufferByte = std::max(copied.seconds - invocations.seconds, 0.0) / (count * 128.0);

  // Bytes cleared: the RGBA32F target.
  const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  const Measured cleared = measure([&] { glClearTexImage(full, 0, GL_RGBA, GL_FLOAT, zero); });
  cpu.clearedByte = cleared.seconds / (double(kWidth) * kHeight * 16.0);

  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, 0);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, 0);
  glDeleteBuffers(1, &source);
  glBindTextureUnit(0, 0);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  glBindVertexArray(0);
  glUseProgram(0);
  const GLuint textures[] = {half, full, image};
  glDeleteTextures(3, textures);
  glDeleteFramebuffers(1, &framebuffer);
  glDeleteVertexArrays(1, &vertexArray);
  glDeleteBuffers(1, &buffer);
  release();
  return true;
}

}  // namespace ocean
