#include "seabed_caustics/layer_spread.h"

#include <algorithm>

#include <glkit/texture.h>

#include "core/gl_sizes.h"
#include "core/shader_library.h"
#include "core/shared_math.h"
#include "core/work_account.h"
#include "seabed_caustics/tile_irradiance_pass.h"

namespace postfx::detail {

Result LayerSpread::init(const std::string& defines, const std::string& label, std::string& error) {
  label_ = label;
  stepName_ = label.substr(label.find('.') + 1) + ".spread";
  const Result r = statistics_.init(defines, label, error);
  if (r != Result::Ok) return r;
  return buildPrograms(
      defines,
      {{blur_,
        label + ".spread",
        {{GL_COMPUTE_SHADER, "postfx/seabed_caustics/wavefront_area_ratio_spread.comp"}}}},
      error);
}

void LayerSpread::ensure(bool on, int resolution, int layers) {
  if (on && rows_ && glkit::storedWidth(rows_) == resolution) {
    GLint depth = 0;
    glGetTextureLevelParameteriv(rows_.id(), 0, GL_TEXTURE_DEPTH, &depth);
    if (depth == layers) return;
  }
  rows_.reset();  // the old size goes first: never two allocated at once
  statistics_.ensure(false);
  if (!on) return;
  rows_ = glkit::createTexture(GL_TEXTURE_2D_ARRAY, (label_ + ".spread_rows").c_str());
  glTextureStorage3D(rows_.id(), 1, GL_R32F, resolution, resolution, layers);
  statistics_.ensure(true);
}

std::uint64_t LayerSpread::allocatedBytes() const {
  return textureBytes(rows_.id(), 4) + statistics_.allocatedBytes();  // R32F
}

std::uint64_t layerSpreadBytes(int resolution, int layers) {
  return std::uint64_t(resolution) * std::uint64_t(resolution) * std::uint64_t(layers) * 4 +
         tileSpreadStatisticsBytes();
}

void LayerSpread::draw(const FrameDesc& frame, const ValidatedTextures& textures,
                       const LayerSpreadDesc& d) {
  const WaterSurface& water = frame.water;
  const int cascades = std::min(water.cascadeCount, kMaxCascades);
  statistics_.measure(frame, textures, d.cell);

  // The blur: one slot, every cascade's cell slopes added up (the grid carries their sum).
  float distances[shared::TILE_MAX_LAYERS] = {};
  for (int k = 0; k < d.layers && k < shared::TILE_MAX_LAYERS; ++k) distances[k] = d.distances[k];
  const GLuint blur = blur_.id();
  glProgramUniform1fv(blur, 1, shared::TILE_MAX_LAYERS, distances);
  glProgramUniform1f(blur, 15, static_cast<float>(d.cell));
  setSpreadCovarianceUniforms(blur, frame, glm::ivec4(0),
                              glm::vec4(static_cast<float>(d.resolution / d.windowSize)), cascades,
                              d.jacobian, d.discCovariance);
  glUseProgram(blur);
  glBindSampler(POSTFX_UNIT_TILE_IRRADIANCE, 0);  // texelFetch only; none of the host's
  const GLuint groups = static_cast<GLuint>((d.resolution + 7) / 8);
  // Rows: the layers into rows_; columns: back into level 0.
  for (int direction = 0; direction < 2; ++direction) {
    const GLuint from = direction == 0 ? d.texture : rows_.id();
    const GLuint to = direction == 0 ? rows_.id() : d.texture;
    glBindTextureUnit(POSTFX_UNIT_TILE_IRRADIANCE, from);
    glBindImageTexture(POSTFX_IMAGE_TILE_IRRADIANCE, to, 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_R32F);
    glProgramUniform4i(blur, 0, d.resolution, direction, d.layers, 0);
    // wavefront_area_ratio_spread.comp per texel: a Gaussian of 2r + 1 taps, r three times the
    // layer's landing spread, at most an eighth of the side (data-dependent: a bound; one fetch
    // where the layer has no spread).
    const std::uint64_t bytes = std::uint64_t(d.resolution) * d.resolution * d.layers * 4;
    const int radius = int(float(d.resolution) * shared::IRRADIANCE_FADE_BAND);
    const double texels = double(d.resolution) * d.resolution;
    work::dispatchCompute(
        {stepName_.c_str(),
         {},
         {perInvocation(2.0 * radius + 1.0, texels, double(groups) * groups * 64.0), 0.0, true},
         {Traffic::readBytes(bytes), Traffic::writeBytes(bytes)}},
        groups, groups, static_cast<GLuint>(d.layers));
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
                    GL_TEXTURE_UPDATE_BARRIER_BIT);
  }
}

}  // namespace postfx::detail
