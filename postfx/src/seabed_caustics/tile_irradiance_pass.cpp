#include "seabed_caustics/tile_irradiance_pass.h"

#include <algorithm>
#include <cmath>

#include <glkit/texture.h>

#include "core/block_check.h"
#include "core/gl_sizes.h"
#include "core/shader_library.h"
#include "core/shared_math.h"
#include "core/work_account.h"
#include "seabed_caustics/caustics_constants.h"
#include "seabed_caustics/cell_slope_statistics.h"

namespace postfx::detail {
namespace {

// The spread's blur buffer: two float copies of every slot's depth layers (0 without it).
std::uint64_t spreadBlurBytes(const TileIrradianceLayout& l) {
  return l.spread ? 2 * std::uint64_t(l.resolution) * std::uint64_t(l.resolution) *
                        std::uint64_t(std::max(l.cascadeCount, 1)) * std::uint64_t(l.layers) * 4
                  : 0;
}

float tileClamp(const FrameDesc& frame) {
  return std::min(frame.caustics.maxIrradiance, shared::TILE_MAX_IRRADIANCE);
}

}  // namespace

// TILE_SPREAD_PARTS partial sums (a vec4) per cascade.
std::uint64_t tileSpreadStatisticsBytes() {
  return std::uint64_t(kMaxCascades) * shared::TILE_SPREAD_PARTS * 16;
}

bool landingSpreadOn(const FrameDesc& frame) {
  return frame.caustics.tileUnresolvedSpread || frame.sun.angularDiameterDegrees > 0.0f;
}

void setSpreadCovarianceUniforms(GLuint program, const FrameDesc& frame,
                                 const glm::ivec4& slotCascade, const glm::vec4& texelsPerMetre,
                                 int cascades) {
  const glm::dvec3 sun = glm::normalize(frame.sun.direction);
  setSpreadCovarianceUniforms(
      program, frame, slotCascade, texelsPerMetre, cascades,
      landingDriftJacobian(sun, frame.water.ior),
      sunDiscLandingCovariance(sun, frame.water.ior,
                               0.5 * glm::radians(double(frame.sun.angularDiameterDegrees))));
}

void setSpreadCovarianceUniforms(GLuint program, const FrameDesc& frame,
                                 const glm::ivec4& slotCascade, const glm::vec4& texelsPerMetre,
                                 int cascades, const glm::dvec4& jacobian,
                                 const glm::dvec3& discCovariance) {
  const glm::vec4 drift(jacobian);
  const glm::vec3 disc(discCovariance);
  glProgramUniform4iv(program, 10, 1, &slotCascade.x);
  glProgramUniform4fv(program, 11, 1, &texelsPerMetre.x);
  glProgramUniform4fv(program, 12, 1, &drift.x);
  glProgramUniform4f(program, 13, disc.x, disc.y, disc.z,
                     frame.caustics.tileUnresolvedSpread ? 1.0f : 0.0f);
  glProgramUniform1i(program, 14, cascades);
}

std::string tileVariantDefines(int groups, int cascadeMask, bool physical) {
  std::string d =
      physical ? "" : "#undef POSTFX_WAVEFRONT_AREA_RATIO\n#define POSTFX_WAVEFRONT_AREA_RATIO 0\n";
  d += "#define POSTFX_TILE_IRRADIANCE 1\n#define POSTFX_TILE_GROUPS ";
  d += std::to_string(groups);
  d += "\n#define POSTFX_TILE_CASCADES ";
  d += std::to_string(cascadeMask);
  d += "\n";
  return d;
}

bool tileIrradianceActive(const FrameDesc& frame) {
  // WavefrontAreaRatio continues its window with this field (validation guarantees that model
  // its feature).
  const CausticsModel model = frame.caustics.model;
  return (model == CausticsModel::TileIrradiance || model == CausticsModel::WavefrontAreaRatio) &&
         frame.water.texture.texture != 0 && frame.sun.direction.y > 0.0;
}

TileIrradianceLayout tileIrradianceLayout(const FrameDesc& frame) {
  TileIrradianceLayout l;
  const CausticsSettings& s = frame.caustics;
  const WaterSurface& water = frame.water;
  l.resolution = s.tileResolution;
  l.layers = s.tileDepthLayers;
  l.groups = l.layers / kTileLayersPerTexel;
  l.maxDepth = s.maxReceiverDepth;
  l.spread = landingSpreadOn(frame);
  const glm::dvec3 up = -refractedSunDown(glm::normalize(frame.sun.direction), water.ior);
  const double upY = std::max(up.y, 1e-6);
  for (int c = 0; c < water.cascadeCount && c < kMaxCascades; ++c) {
    // Paraxial modulation at the deepest layer, as the cascade skip of the other models.
    const double modulation =
        (1.0 - 1.0 / double(water.ior)) * water.rmsLaplacian[c] / upY * l.maxDepth;
    const double cut = s.tileMinModulation;
    const bool unknown = !(water.rmsLaplacian[c] > 0.0);
    if (unknown || modulation >= cut) {
      l.slot[c] = l.cascadeCount++;
      l.cascadeMask |= 1 << c;
    }
  }
  return l;
}

std::uint64_t tileIrradianceBytes(const TileIrradianceLayout& l) {
  const std::uint64_t arrayLayers = std::uint64_t(std::max(l.cascadeCount * l.groups, 1));
  std::uint64_t texels = 0;
  for (int level = 0; level < glkit::mipLevelCount(l.resolution); ++level) {
    const std::uint64_t side = std::max(l.resolution >> level, 1);
    texels += side * side;
  }
  const std::uint64_t accumulators = std::uint64_t(l.resolution) * std::uint64_t(l.resolution) *
                                     std::uint64_t(std::max(l.cascadeCount, 1)) *
                                     std::uint64_t(l.layers);
  const std::uint64_t spread = l.spread ? spreadBlurBytes(l) + tileSpreadStatisticsBytes() : 0;
  return texels * arrayLayers * 8 + accumulators * 4 + spread;
}

std::uint64_t TileIrradiancePass::allocatedBytes() const {
  return textureBytes(texture_.id(), 8) + bufferBytes(accumulators_.id()) +  // RGBA16F
         bufferBytes(spreadStatisticsBuffer_.id()) + bufferBytes(blur_.id());
}

Result TileIrradiancePass::init(const std::string& defines, std::string& error) {
  return buildPrograms(
      defines,
      {{scatter_,
        "postfx.tile_irradiance.scatter",
        {{GL_COMPUTE_SHADER, "postfx/seabed_caustics/tile_irradiance_scatter.comp"}},
        "#define POSTFX_TILE_FOOTPRINT 0\n"},
       {scatterFootprint_,
        "postfx.tile_irradiance.scatter_footprint",
        {{GL_COMPUTE_SHADER, "postfx/seabed_caustics/tile_irradiance_scatter.comp"}},
        "#define POSTFX_TILE_FOOTPRINT 1\n"},
       {resolve_,
        "postfx.tile_irradiance.resolve",
        {{GL_COMPUTE_SHADER, "postfx/seabed_caustics/tile_irradiance_resolve.comp"}}},
       {downsample_,
        "postfx.tile_irradiance.downsample",
        {{GL_COMPUTE_SHADER, "postfx/seabed_caustics/tile_irradiance_downsample.comp"}}},
       {spreadStatistics_,
        "postfx.tile_irradiance.spread_statistics",
        {{GL_COMPUTE_SHADER, "postfx/seabed_caustics/tile_irradiance_spread.comp"}}},
       {spreadBox_,
        "postfx.tile_irradiance.spread_box",
        {{GL_COMPUTE_SHADER, "postfx/seabed_caustics/tile_irradiance_spread_box.comp"}}},
       {spreadPack_,
        "postfx.tile_irradiance.spread_pack",
        {{GL_COMPUTE_SHADER, "postfx/seabed_caustics/tile_irradiance_spread_pack.comp"}}}},
      error);
}

Result TileIrradiancePass::reserve(const FrameDesc& frame, std::string& error) {
  layout_ = tileIrradianceLayout(frame);
  const TileIrradianceLayout& l = layout_;
  const int arrayLayers = std::max(l.cascadeCount * l.groups, 1);
  if (!texture_ || textureResolution_ != l.resolution || textureLayers_ != arrayLayers) {
    texture_.reset();  // the old size goes first: never two of them allocated at once
    texture_ = glkit::createTexture(GL_TEXTURE_2D_ARRAY, "postfx.tile_irradiance.irradiance");
    glTextureStorage3D(texture_.id(), glkit::mipLevelCount(l.resolution), GL_RGBA16F, l.resolution,
                       l.resolution, arrayLayers);
    textureResolution_ = l.resolution;
    textureLayers_ = arrayLayers;
  }
  const GLsizeiptr bytes = GLsizeiptr(l.resolution) * l.resolution * std::max(l.cascadeCount, 1) *
                           l.layers * GLsizeiptr(sizeof(GLuint));
  if (!accumulators_ || accumulatorBytes_ != bytes) {
    accumulators_.reset();
    accumulators_ = glkit::createBuffer(bytes, nullptr, GL_DYNAMIC_STORAGE_BIT,
                                        "postfx.tile_irradiance.accumulators");
    // Zero once; the resolve leaves them zero for the next frame.
    const GLuint zero = 0;
    glClearNamedBufferData(accumulators_.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
    accumulatorBytes_ = bytes;
  }
  // The spread's buffers only while it is on: a frame without it holds none.
  const GLsizeiptr blurBytes = static_cast<GLsizeiptr>(spreadBlurBytes(l));
  if (blurBytes_ != blurBytes) {
    blur_.reset();
    spreadStatisticsBuffer_.reset();
    if (blurBytes > 0) {
      blur_ = glkit::createBuffer(blurBytes, nullptr, GL_DYNAMIC_STORAGE_BIT,
                                  "postfx.tile_irradiance.spread_blur");
      spreadStatisticsBuffer_ =
          glkit::createBuffer(GLsizeiptr(tileSpreadStatisticsBytes()), nullptr,
                              GL_DYNAMIC_STORAGE_BIT, "postfx.tile_irradiance.spread_statistics");
    }
    blurBytes_ = blurBytes;
  }
  GLint64 allocated = 0, blurAllocated = 0;
  glGetNamedBufferParameteri64v(accumulators_.id(), GL_BUFFER_SIZE, &allocated);
  if (blur_) glGetNamedBufferParameteri64v(blur_.id(), GL_BUFFER_SIZE, &blurAllocated);
  if (glkit::storedWidth(texture_) != l.resolution || allocated != bytes ||
      blurAllocated != blurBytes) {
    error = "caustics: the driver could not allocate the tile irradiance (tileResolution " +
            std::to_string(l.resolution) + ")";
    return Result::OutOfMemory;
  }
  return Result::Ok;
}

void TileIrradiancePass::draw(const FrameDesc& frame, const ValidatedTextures& textures) {
  const TileIrradianceLayout& l = layout_;
  if (l.cascadeCount == 0) return;
  const WaterSurface& water = frame.water;
  const glm::dvec3 sun = glm::normalize(frame.sun.direction);
  const glm::dvec3 down = refractedSunDown(sun, water.ior);
  const glm::dvec2 flatDrift = glm::dvec2(down.x, down.z) / std::max(-down.y, 1e-6);
  const double flatT = shared::fresnelTransmittance(static_cast<float>(sun.y), water.ior);
  // tilePointsPerTexel per irradiance texel and side, each reading its cell's mean water.
  const int points = l.resolution * frame.caustics.tilePointsPerTexel;
  const double perPoint = double(l.resolution) * l.resolution / (double(points) * points);
  float depths[shared::TILE_MAX_LAYERS] = {};
  for (int k = 0; k < l.layers; ++k)
    depths[k] = shared::tileLayerDepth(k, l.layers, static_cast<float>(l.maxDepth));

  // Points at least as dense as the water's texels resolve every slope it has: nothing
  // unresolved softens the pattern, and where the light diverges the points' own footprints are
  // wider than a texel (the bilinear split alone would leave a grid of dots in the dark).
  const int waterSide = std::max(textures.water.width, textures.water.height);
  const GLuint scatter = points >= waterSide ? scatterFootprint_.id() : scatter_.id();
  glProgramUniform4f(scatter, 2, static_cast<float>(sun.x), static_cast<float>(sun.y),
                     static_cast<float>(sun.z), water.ior);
  glProgramUniform4f(scatter, 3, static_cast<float>(flatDrift.x), static_cast<float>(flatDrift.y),
                     saturatedFloat(flatT > 0.0 ? 1.0 / flatT : 0.0),
                     static_cast<float>(perPoint * double(shared::TILE_FIXED_POINT)));
  glProgramUniform1i(scatter, 4, l.layers);
  glProgramUniform1fv(scatter, 5, shared::TILE_MAX_LAYERS, depths);
  glProgramUniform1f(scatter, 13,
                     textures.waterMipmapped && waterSide > points
                         ? static_cast<float>(std::log2(double(waterSide) / points))
                         : 0.0f);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, POSTFX_STORAGE_TILE_ACCUMULATORS, accumulators_.id());
  glUseProgram(scatter);
  const GLuint pointGroups = static_cast<GLuint>((points + 7) / 8);
  // tile_irradiance_scatter.comp per point: its water texel (and its four neighbours' with the
  // footprint), then per depth layer its flux added to the 2 x 2 texels around its landing, or
  // to the up to 5 x 5 its footprint covers (a bound: most cover 2 x 2 to 3 x 3).
  const bool footprint = scatter == scatterFootprint_.id();
  const double padded = double(pointGroups) * pointGroups * 64.0, inGrid = double(points) * points;
  const Step scatterStep{
      "tile_irradiance.scatter",
      {},
      {perInvocation(footprint ? 5.0 : 1.0, inGrid, padded),
       perInvocation(double(l.layers) * (footprint ? 25 : 4), inGrid, padded), footprint},
      {Traffic::read(frame.water.texture.texture), Traffic::writeBuffer(accumulators_.id())}};
  for (int c = 0; c < water.cascadeCount && c < kMaxCascades; ++c) {
    if (l.slot[c] < 0) continue;
    glProgramUniform1i(scatter, 0, c);
    glProgramUniform4f(scatter, 1, static_cast<float>(points), static_cast<float>(l.resolution),
                       static_cast<float>(water.tileSize[c]),
                       static_cast<float>(l.slot[c] * l.layers));
    work::dispatchCompute(scatterStep, pointGroups, pointGroups, 1);
  }
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);

  if (l.spread) {
    drawSpread(frame, depths, waterSide);
  } else {
    const GLuint resolve = resolve_.id();
    glUseProgram(resolve);
    glBindImageTexture(POSTFX_IMAGE_TILE_IRRADIANCE, texture_.id(), 0, GL_TRUE, 0, GL_WRITE_ONLY,
                       GL_RGBA16F);
    const GLuint texelGroups = static_cast<GLuint>((l.resolution + 7) / 8);
    // tile_irradiance_resolve.comp: buffer reads and image writes only.
    const double share = 1.0 / std::max(l.cascadeCount, 1);
    const Step resolveStep{"tile_irradiance.resolve",
                           {},
                           {},
                           {Traffic::readBuffer(accumulators_.id(), share),
                            Traffic::writeBuffer(accumulators_.id(), share),
                            Traffic::writeBytes(std::uint64_t(l.resolution) * l.resolution *
                                                std::uint64_t(l.groups) * 8)}};
    for (int c = 0; c < water.cascadeCount && c < kMaxCascades; ++c) {
      if (l.slot[c] < 0) continue;
      glProgramUniform4f(resolve, 0, static_cast<float>(l.resolution),
                         static_cast<float>(l.slot[c] * l.layers),
                         static_cast<float>(l.slot[c] * l.groups), tileClamp(frame));
      work::dispatchCompute(resolveStep, texelGroups, texelGroups, static_cast<GLuint>(l.groups));
    }
  }
  // The mip chain from the image writes, level by level (each dispatch reads the level the one
  // before wrote); the caustics pass then samples it. The unit is the one the caustics pass
  // binds the field to next (GlStateGuard restores it); texelFetch ignores its sampler.
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
  const GLuint downsample = downsample_.id();
  glUseProgram(downsample);
  glBindTextureUnit(POSTFX_UNIT_TILE_IRRADIANCE, texture_.id());
  glBindSampler(POSTFX_UNIT_TILE_IRRADIANCE, 0);  // whatever the host left there: none
  const int levels = glkit::mipLevelCount(l.resolution);
  for (int level = 1; level < levels; ++level) {
    const int side = std::max(l.resolution >> level, 1);
    glBindImageTexture(POSTFX_IMAGE_TILE_IRRADIANCE, texture_.id(), level, GL_TRUE, 0,
                       GL_WRITE_ONLY, GL_RGBA16F);
    glProgramUniform2i(downsample, 0, side, level - 1);
    const GLuint groups = static_cast<GLuint>((side + 7) / 8);
    // tile_irradiance_downsample.comp: the four finer texels of each coarser one.
    const std::uint64_t texels = std::uint64_t(side) * side * std::uint64_t(textureLayers_);
    work::dispatchCompute(
        {"tile_irradiance.downsample",
         {},
         {perInvocation(4.0, double(side) * side, double(groups) * groups * 64.0)},
         {Traffic::readBytes(4 * texels * 8), Traffic::writeBytes(texels * 8)}},
        groups, groups, static_cast<GLuint>(textureLayers_));
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
  }
}

void TileIrradiancePass::drawSpread(const FrameDesc& frame, const float* depths, int waterSide) {
  const TileIrradianceLayout& l = layout_;
  const WaterSurface& water = frame.water;
  const int cascades = std::min(water.cascadeCount, kMaxCascades);

  // Every cascade's slope statistics, in parts.
  const GLuint statistics = spreadStatistics_.id();
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, POSTFX_STORAGE_TILE_SPREAD,
                   spreadStatisticsBuffer_.id());
  const float points = static_cast<float>(l.resolution * frame.caustics.tilePointsPerTexel);
  glProgramUniform4f(statistics, 0, points, points, points, points);
  glUseProgram(statistics);
  // tile_irradiance_spread.comp: CellSlopeStatistics::cascadeFetches per cascade.
  {
    const double perInvocation = CellSlopeStatistics::cascadeFetches(points, waterSide);
    work::dispatchCompute({"tile_irradiance.spread_statistics",
                           {},
                           {perInvocation, 0.0},
                           {Traffic::readBytes(static_cast<std::uint64_t>(
                               perInvocation * cascades * shared::TILE_SPREAD_PARTS * 256 * 8))}},
                          static_cast<GLuint>(cascades),
                          static_cast<GLuint>(shared::TILE_SPREAD_PARTS), 1);
  }
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);

  // The blur: rows, columns and the diagonal, every cascade and layer in each dispatch.
  glm::ivec4 slotCascade(0);
  glm::vec4 texelsPerMetre(0.0f);
  for (int c = 0; c < cascades; ++c) {
    if (l.slot[c] < 0) continue;
    slotCascade[l.slot[c]] = c;
    texelsPerMetre[l.slot[c]] = static_cast<float>(l.resolution / water.tileSize[c]);
  }
  const GLuint box = spreadBox_.id();
  glProgramUniform1fv(box, 1, shared::TILE_MAX_LAYERS, depths);
  setSpreadCovarianceUniforms(box, frame, slotCascade, texelsPerMetre, cascades);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, POSTFX_STORAGE_TILE_ACCUMULATORS, accumulators_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, POSTFX_STORAGE_TILE_BLUR, blur_.id());
  glUseProgram(box);
  const int n = l.resolution;
  const GLuint lineGroups = static_cast<GLuint>((n + 63) / 64);
  // tile_irradiance_spread_box.comp: one line of one layer per invocation, buffers only.
  const Step boxStep{"tile_irradiance.spread_blur",
                     {},
                     {},
                     {Traffic::readBuffer(blur_.id(), 0.5), Traffic::writeBuffer(blur_.id(), 0.5)}};
  for (int direction = 0; direction < 3; ++direction) {
    glProgramUniform4i(box, 0, n, direction, l.cascadeCount, l.layers);
    work::dispatchCompute(boxStep, lineGroups, static_cast<GLuint>(l.layers),
                          static_cast<GLuint>(l.cascadeCount));
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  }
  const GLuint pack = spreadPack_.id();
  glProgramUniform3f(pack, 0, static_cast<float>(n), static_cast<float>(l.layers),
                     tileClamp(frame));
  glBindImageTexture(POSTFX_IMAGE_TILE_IRRADIANCE, texture_.id(), 0, GL_TRUE, 0, GL_WRITE_ONLY,
                     GL_RGBA16F);
  glUseProgram(pack);
  const GLuint texelGroups = static_cast<GLuint>((n + 7) / 8);
  // tile_irradiance_spread_pack.comp: four layers of the blur into each RGBA16F texel.
  work::dispatchCompute(
      {"tile_irradiance.spread_pack",
       {},
       {},
       {Traffic::readBuffer(blur_.id(), 0.5),
        Traffic::writeBytes(std::uint64_t(n) * n * std::uint64_t(l.cascadeCount * l.groups) * 8)}},
      texelGroups, texelGroups, static_cast<GLuint>(l.cascadeCount * l.groups));
  // Each accumulator was read by several texels: zeroed for the next frame only now.
  const GLuint zero = 0;
  glClearNamedBufferData(accumulators_.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
  work::noteClear("tile_irradiance.clear", static_cast<std::uint64_t>(accumulatorBytes_));
}

}  // namespace postfx::detail
