#pragma once
// Where the WavefrontAreaRatio model's grids and irradiance texture lie this frame, computed in
// double from the FrameDesc: the receiver window (camera-centred, snapped to whole texels in
// world space so the pattern does not swim), each depth layer's surface grid (snapped to whole
// grid cells, moved toward the sun by the flat-water drift to that depth), and the depths.
#include <cstdint>

#include <glm/glm.hpp>

#include <postfx/postfx.h>

namespace postfx::detail {

inline constexpr int kMaxWavefrontAreaRatioLayers = 8;
// The surface grid spans the window plus this fraction of it on each side: the refracted rays
// drift sideways with the slopes, and light entering outside the window's shadow on the
// surface still lands inside. Drift beyond it shows as a dimmer rim, inside the fade band
// (shared::IRRADIANCE_FADE_BAND).
inline constexpr double kGridMargin = 0.125;

struct WavefrontAreaRatioLayout {
  int resolution = 0;  // texels and grid cells' nominal count per side
  int layers = 0;
  double windowSize = 0.0, texel = 0.0;
  glm::dvec2 windowOrigin{0.0};  // world xz of texel (0, 0)'s corner
  double cell = 0.0;             // grid spacing (m)
  int cells = 0;                 // grid cells per side (resolution + 1: snapping headroom)
  double depth[kMaxWavefrontAreaRatioLayers] = {};
  glm::dvec2 gridOrigin[kMaxWavefrontAreaRatioLayers] = {};  // world xz of grid vertex (0, 0)
  // The layers are blurred by the landing spread of the slopes finer than a cell
  // (CausticsSettings::tileUnresolvedSpread) and of the sun's disc (Sun::angularDiameterDegrees).
  bool spread = false;
};

// Depth of layer k of `layers` (m below the level).
double wavefrontAreaRatioLayerDepth(int k, int layers, double maxDepth);

// Requires validated settings and a sun above the horizon.
WavefrontAreaRatioLayout wavefrontAreaRatioLayout(const FrameDesc& frame);

// Mip levels of the irradiance layers (the base and up to shared::IRRADIANCE_MIP_LEVELS more).
int wavefrontAreaRatioMipLevels(int resolution);
// GPU memory the pass allocates for `gridResolution` and `depthLayers`: the R32F layers with
// their mip levels, and the grid points (two vec4 per point, (gridResolution + 2)^2 points);
// with `spread`, one more R32F level 0 per layer and the slope statistics.
// The memory estimate and WavefrontAreaRatioPass::allocatedBytes() must agree (a test checks).
std::uint64_t wavefrontAreaRatioBytes(int gridResolution, int depthLayers, bool spread);

}  // namespace postfx::detail
