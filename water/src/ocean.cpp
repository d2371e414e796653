#include <postfx/water/ocean.h>

#include <cmath>
#include <cstring>
#include <numbers>
#include <vector>

#include <glkit/current_context.h>
#include <glkit/program.h>
#include <glkit/texture.h>
#include <postfx/water/initial_spectrum.h>
#include <postfx/water/spectrum.h>

#include "gl_state_guard.h"
#include "shader_interface.h"

namespace postfx::water {
namespace {

using namespace detail;

static_assert(WATER_MAX_CASCADES == kMaxCascades, "C++ and GLSL disagree on the cascade limit");

// Checks the GL limits the chosen resolution needs; the shaders use one workgroup of N/2
// invocations per line with two RGBA32F lines in shared memory.
Result checkLimits(const OceanDesc& desc, size_t spectrumBytes, std::string& error) {
  GLint groupSize = 0, invocations = 0, sharedBytes = 0, textureSize = 0, layers = 0;
  GLint groupCount = 0, imageUnits = 0;
  GLint64 storageBlock = 0;
  glGetIntegeri_v(GL_MAX_COMPUTE_WORK_GROUP_SIZE, 0, &groupSize);
  glGetIntegeri_v(GL_MAX_COMPUTE_WORK_GROUP_COUNT, 0, &groupCount);
  glGetIntegerv(GL_MAX_COMPUTE_WORK_GROUP_INVOCATIONS, &invocations);
  glGetIntegerv(GL_MAX_COMPUTE_SHARED_MEMORY_SIZE, &sharedBytes);
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &textureSize);
  glGetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &layers);
  glGetIntegerv(GL_MAX_IMAGE_UNITS, &imageUnits);
  glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &storageBlock);
  const int n = desc.resolution;
  const bool fits =
      n / 2 <= groupSize && n / 2 <= invocations && n <= groupCount && 2 * n * 16 <= sharedBytes &&
      n <= textureSize && desc.cascadeCount * WATER_SCRATCH_LAYERS_PER_CASCADE <= layers &&
      imageUnits >= WATER_IMAGE_UNIT_COUNT && static_cast<GLint64>(spectrumBytes) <= storageBlock;
  if (fits) return Result::Ok;
  error = "resolution " + std::to_string(n) + " exceeds this GL implementation's limits";
  return Result::Unsupported;
}

GLuint createArrayTexture(GLenum format, int n, int layers, int levels, std::string_view name) {
  GLuint texture = 0;
  glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &texture);
  glTextureStorage3D(texture, levels, format, n, n, layers);
  const bool mipmapped = levels > 1;
  glTextureParameteri(texture, GL_TEXTURE_MIN_FILTER,
                      mipmapped ? GL_LINEAR_MIPMAP_LINEAR : GL_NEAREST);
  glTextureParameteri(texture, GL_TEXTURE_MAG_FILTER, mipmapped ? GL_LINEAR : GL_NEAREST);
  glTextureParameteri(texture, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTextureParameteri(texture, GL_TEXTURE_WRAP_T, GL_REPEAT);
  glkit::label(GL_TEXTURE, texture, name);
  return texture;
}

// The spectrum buffer: vec4 amplitude[modes] (a.re, a.im, b.re, b.im), then uint cycles[modes].
std::vector<unsigned char> packSpectrum(const InitialSpectrum& spectrum) {
  const size_t modes = spectrum.a.size();
  std::vector<float> amplitudes(modes * 4);
  for (size_t i = 0; i < modes; ++i) {
    amplitudes[4 * i + 0] = static_cast<float>(spectrum.a[i].real());
    amplitudes[4 * i + 1] = static_cast<float>(spectrum.a[i].imag());
    amplitudes[4 * i + 2] = static_cast<float>(spectrum.b[i].real());
    amplitudes[4 * i + 3] = static_cast<float>(spectrum.b[i].imag());
  }
  std::vector<unsigned char> bytes(modes * (16 + 4));
  std::memcpy(bytes.data(), amplitudes.data(), modes * 16);
  std::memcpy(bytes.data() + modes * 16, spectrum.cycles.data(), modes * 4);
  return bytes;
}

}  // namespace

Result Ocean::create(const OceanDesc& desc, std::unique_ptr<Ocean>& out, std::string& error) {
  out.reset();
  if (Result result = validateOceanDesc(desc, error); result != Result::Ok) return result;
  if (!glkit::hasCurrentContext()) {
    error = "Ocean::create: no current GL context on this thread";
    return Result::NoContext;
  }
  const size_t modes = static_cast<size_t>(desc.resolution) * desc.resolution * desc.cascadeCount;
  if (Result result = checkLimits(desc, modes * 20, error); result != Result::Ok) return result;
  std::unique_ptr<Ocean> ocean(new Ocean(desc));
  // On failure the half-built Ocean's destructor deletes whatever it had created.
  if (Result result = ocean->initialise(error); result != Result::Ok) return result;
  out = std::move(ocean);
  return Result::Ok;
}

Result Ocean::initialise(std::string& error) {
  const int n = desc_.resolution;
  const int cascades = desc_.cascadeCount;
  const std::string defines = "#define WATER_N " + std::to_string(n) + "\n#define WATER_LOG2_N " +
                              std::to_string(std::countr_zero(static_cast<unsigned>(n))) +
                              "\n#define WATER_MODE_COUNT " +
                              std::to_string(static_cast<size_t>(n) * n * cascades) + "\n";
  // Plain names: the public header holds them without glkit; the destructor deletes them.
  rowProgram_ =
      glkit::buildProgram(shaderLibrary(), {{GL_COMPUTE_SHADER, "water/spectrum_rows.comp"}},
                          defines, "water.spectrum_rows", error)
          .release();
  if (rowProgram_ == 0) return Result::ShaderCompileFailed;
  columnProgram_ =
      glkit::buildProgram(shaderLibrary(), {{GL_COMPUTE_SHADER, "water/columns_assemble.comp"}},
                          defines, "water.columns_assemble", error)
          .release();
  if (columnProgram_ == 0) return Result::ShaderCompileFailed;

  waveStats_ = cascadeWaveStats(desc_);
  const std::vector<unsigned char> spectrum = packSpectrum(buildInitialSpectrum(desc_));
  glCreateBuffers(1, &spectrumBuffer_);
  glNamedBufferStorage(spectrumBuffer_, static_cast<GLsizeiptr>(spectrum.size()), spectrum.data(),
                       0);
  glkit::label(GL_BUFFER, spectrumBuffer_, "water.spectrum");

  const int levels = glkit::mipLevelCount(n);
  scratch_ = createArrayTexture(GL_RGBA32F, n, cascades * WATER_SCRATCH_LAYERS_PER_CASCADE, 1,
                                "water.fft_scratch");
  slope_ = createArrayTexture(GL_RGBA16F, n, cascades, levels, "water.slope");
  displacement_ = createArrayTexture(GL_RGBA16F, n, cascades, levels, "water.displacement");

  size_t outputTexels = 0;
  for (int level = 0; level < levels; ++level) {
    const size_t side = static_cast<size_t>(n >> level);
    outputTexels += side * side * cascades;
  }
  const size_t scratchBytes =
      static_cast<size_t>(n) * n * cascades * WATER_SCRATCH_LAYERS_PER_CASCADE * 16;
  gpuBytes_ = spectrum.size() + scratchBytes + 2 * outputTexels * 8;

  for (GLenum glError = glGetError(); glError != GL_NO_ERROR; glError = glGetError()) {
    error = "GL error " + std::to_string(glError) + " while allocating the ocean's resources";
    return Result::GlError;
  }
  // The textures hold the surface at t = 0 from the start, never undefined texels.
  return update(0.0, error);
}

Ocean::~Ocean() {
  glDeleteProgram(rowProgram_);
  glDeleteProgram(columnProgram_);
  glDeleteBuffers(1, &spectrumBuffer_);
  const GLuint textures[] = {scratch_, slope_, displacement_};
  glDeleteTextures(3, textures);
}

Result Ocean::update(double timeSeconds) {
  std::string ignored;
  return update(timeSeconds, ignored);
}

Result Ocean::update(double timeSeconds, std::string& error) {
  if (!std::isfinite(timeSeconds)) {
    error = "update: time must be finite";
    return Result::InvalidArgument;
  }
  if (!glkit::hasCurrentContext()) {
    error = "update: no current GL context on this thread";
    return Result::NoContext;
  }
  const uint32_t phase = loopPhase(timeSeconds, desc_.loopPeriod);
  const int n = desc_.resolution;
  const int cascades = desc_.cascadeCount;

  GlStateGuard guard;
  glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, -1, "postfx::water::Ocean::update");

  float waveSteps[kMaxCascades] = {};
  for (int c = 0; c < cascades; ++c) {
    waveSteps[c] = static_cast<float>(2.0 * std::numbers::pi / desc_.tileSize[c]);
  }
  glProgramUniform1ui(rowProgram_, glGetUniformLocation(rowProgram_, "uLoopPhase"), phase);
  glProgramUniform1f(rowProgram_, glGetUniformLocation(rowProgram_, "uChoppiness"),
                     static_cast<float>(desc_.choppiness));
  glProgramUniform1fv(rowProgram_, glGetUniformLocation(rowProgram_, "uWaveStep"), kMaxCascades,
                      waveSteps);

  glUseProgram(rowProgram_);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, WATER_SPECTRUM_BINDING, spectrumBuffer_);
  glBindImageTexture(WATER_SCRATCH_UNIT, scratch_, 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  glDispatchCompute(static_cast<GLuint>(n), static_cast<GLuint>(cascades), 1);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);

  glUseProgram(columnProgram_);
  glBindImageTexture(WATER_SCRATCH_UNIT, scratch_, 0, GL_TRUE, 0, GL_READ_ONLY, GL_RGBA32F);
  glBindImageTexture(WATER_SLOPE_UNIT, slope_, 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA16F);
  glBindImageTexture(WATER_DISPLACEMENT_UNIT, displacement_, 0, GL_TRUE, 0, GL_WRITE_ONLY,
                     GL_RGBA16F);
  glDispatchCompute(static_cast<GLuint>(n), static_cast<GLuint>(cascades), 1);
  // Level 0 must be complete before the mip chain is built and before anyone samples it; the
  // image bit also orders the next frame's scratch writes after this frame's reads.
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT |
                  GL_TEXTURE_UPDATE_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
  glGenerateTextureMipmap(slope_);
  glGenerateTextureMipmap(displacement_);

  glPopDebugGroup();
  return Result::Ok;
}

}  // namespace postfx::water
