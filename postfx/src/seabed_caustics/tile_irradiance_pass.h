#pragma once
// The TileIrradiance model's per-frame pre-pass: for every cascade whose waves can focus light
// within CausticsSettings::maxReceiverDepth, the caustic irradiance it makes alone, at
// tileDepthLayers depths, over one period of its tile (see
// postfx/seabed_caustics/postfx_tile_irradiance.h). Two compute dispatches per cascade (scatter,
// resolve) into a plugin-owned RGBA16F 2D array (four depth layers per texel, one array layer per
// group of four), then its mip chain: the caustics pass filters irradiance, which is linear in the
// light, so a far pixel gets the mean of what its footprint receives instead of a sparkle of
// aliased lines. Its cost does not depend on the screen size: tileResolution^2 texels and (2 x
// tileResolution)^2 (at least the water texture's size) refracted points per cascade.
#include <epoxy/gl.h>

#include <cstdint>
#include <string>

#include <glkit/handle.h>
#include <glkit/program.h>
#include <postfx/postfx.h>

#include "core/validation.h"

namespace postfx::detail {

inline constexpr int kTileLayersPerTexel = 4;

// The slope statistics' buffer (tile_irradiance_spread_statistics.glsl's partial sums, every
// cascade), which the wavefront area ratio's spread fills too.
std::uint64_t tileSpreadStatisticsBytes();
// Whether the fields are blurred by a landing spread at all: the unresolved slopes'
// (CausticsSettings::tileUnresolvedSpread) or the sun disc's (Sun::angularDiameterDegrees > 0).
// Both the tile field and the wavefront area ratio's window follow it.
bool landingSpreadOn(const FrameDesc& frame);
// The landing covariance's uniforms of tile_irradiance_spread_statistics.glsl's reader
// (locations 10 to 14) on `program`: each slot's cascade and texels per metre, the landing drift
// and the sun disc's covariance of this frame's sun, whether the unresolved slopes spread.
void setSpreadCovarianceUniforms(GLuint program, const FrameDesc& frame,
                                 const glm::ivec4& slotCascade, const glm::vec4& texelsPerMetre,
                                 int cascades);
// The same with the landing's slope Jacobian and sun-disc covariance given (the reflected
// light's, whose mirror moves its landing by other amounts than refraction).
void setSpreadCovarianceUniforms(GLuint program, const FrameDesc& frame,
                                 const glm::ivec4& slotCascade, const glm::vec4& texelsPerMetre,
                                 int cascades, const glm::dvec4& jacobian,
                                 const glm::dvec3& discCovariance);

struct TileIrradianceLayout {
  int resolution = 0;  // irradiance texels per tile side
  int layers = 0;      // depth layers per cascade (a multiple of 4)
  int groups = 0;      // RGBA array layers per cascade: layers / 4
  double maxDepth = 0.0;
  int cascadeCount = 0;  // cascades with irradiance (the others read 1)
  int cascadeMask = 0;   // bit c: cascade c has irradiance (compiled into the caustics pass)
  // Per cascade: its index among the cascades with irradiance, -1 when it has none.
  int slot[kMaxCascades] = {-1, -1, -1, -1};
  // The layers are convolved with a landing spread
  // (postfx/seabed_caustics/postfx_tile_irradiance.h): of the slopes the points do not resolve
  // (CausticsSettings::tileUnresolvedSpread) and of the sun's disc (Sun::angularDiameterDegrees).
  bool spread = false;
};

// Which cascades the frame needs: those whose first-order irradiance modulation at
// maxReceiverDepth (WaterSurface::rmsLaplacian) reaches tileMinModulation, and every cascade
// whose statistics the host left unknown (0). Requires validated settings.
TileIrradianceLayout tileIrradianceLayout(const FrameDesc& frame);

// GPU memory the pass allocates for layout `l`: the RGBA16F array (l.groups layers per cascade
// with irradiance, at least one) with its full mip chain, and a uint accumulator per texel,
// depth layer and cascade (at least one cascade); with the spread, the blur's two copies of
// every layer (a float per texel) and the slope statistics' partial sums.
// The memory estimate and TileIrradiancePass::allocatedBytes() must agree (a test checks).
std::uint64_t tileIrradianceBytes(const TileIrradianceLayout& l);

// The #defines of a program variant that reads the tile irradiance (caustics or god rays):
// `groups` RGBA fetches per cascade (1 or 2), the cascades in `cascadeMask` (bit c: cascade c),
// and, unless `physical` (the WavefrontAreaRatio window continued by the field), the window's
// lookup compiled out.
std::string tileVariantDefines(int groups, int cascadeMask, bool physical);

// Whether the frame computes the tile irradiance: the TileIrradiance model, and the
// WavefrontAreaRatio model beyond its window. It needs a water texture and a sun above the
// horizon; otherwise nothing is computed (TileIrradiance then adds no light).
bool tileIrradianceActive(const FrameDesc& frame);

class TileIrradiancePass {
 public:
  Result init(const std::string& defines, std::string& error);

  // Allocates this frame's irradiance array and accumulators (before any pass adds light);
  // OutOfMemory with a message when the driver could not.
  Result reserve(const FrameDesc& frame, std::string& error);
  // Records the pre-pass. Expects the water texture bound on its unit (CausticsPass::bindState);
  // binds its programs, its storage binding and image unit (postfx/common/postfx_bindings.h; the
  // caller's state guard restores them).
  void draw(const FrameDesc& frame, const ValidatedTextures& textures);

  GLuint texture() const { return texture_.id(); }
  const TileIrradianceLayout& layout() const { return layout_; }
  // What its array and accumulators hold now, asked of GL (0 before the first frame).
  std::uint64_t allocatedBytes() const;

 private:
  // The unresolved-slope spread: statistics, then per cascade the box passes of its blur.
  void drawSpread(const FrameDesc& frame, const float* depths, int waterSide);

  // scatter_ splits each point's flux bilinearly, scatterFootprint_ over its refracted footprint.
  glkit::Program scatter_, scatterFootprint_, resolve_, downsample_;
  glkit::Program spreadStatistics_, spreadBox_, spreadPack_;
  glkit::Texture texture_;
  glkit::Buffer accumulators_, spreadStatisticsBuffer_, blur_;
  int textureResolution_ = 0, textureLayers_ = 0;
  GLsizeiptr accumulatorBytes_ = 0, blurBytes_ = 0;
  TileIrradianceLayout layout_{};
};

}  // namespace postfx::detail
