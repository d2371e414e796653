#pragma once
// Local, non-periodic water (Feature::LocalWater): pools, ripples, wakes, a harbour basin. Beside
// the periodic cascades (WaterSurface::texture), a frame may give up to kMaxLocalWater regions,
// each a world-placed rectangle with a height/slope texture of its own (a ripple simulation, a
// wake). Its surface is refracted as a grid onto the receivers below it (the wavefront area ratio,
// folds summed) once per frame for every view; under the region that light replaces the periodic
// field's, blended into it over `edgeBlend`; outside it the seabed caustics do not change (bit
// for bit). The seabed caustics (any CausticsModel) and the god rays read it; a god-ray view ray
// that passes under a region takes its light, so shafts change outside the rectangle too. Walls and
// overhangs inside a region get the light that entered the water where the refracted sun through
// them meets the level (as webgl-water lights its pool's walls). docs/integration.md, "Local
// water".
#include <cstdint>

#include <glm/glm.hpp>

#include <postfx/frame_desc.h>
#include <postfx/range.h>

namespace postfx {

inline constexpr int kMaxLocalWater = 4;
inline constexpr Range<double> kLocalWaterSizeRange{1e-2, 1e5};      // m, each side
inline constexpr Range<double> kLocalWaterRotationRange{-1e3, 1e3};  // radians
inline constexpr Range<int> kLocalWaterGridRange{16, 2048};          // cells along the longer side
inline constexpr Range<int> kLocalWaterLayerRange{1, 8};
inline constexpr Range<float> kLocalWaterDepthRange{1e-3f, 1e4f};  // m

enum class LocalWaterMode : std::uint8_t {
  // The region's surface is added to the cascades' (a wake, a swimmer's ripples, rain rings on
  // the sea): its light is the sea's, corrected by what the region's heights change (the
  // difference of the grid refracted with and without them), so a region of zero height
  // changes nothing, bit for bit.
  Add,
  // The region is water of its own (a pool, a fountain basin): the cascades are not read under
  // it.
  Replace,
};

struct LocalWater {
  // World xz of the rectangle's centre (m), within +-1e9 like every world coordinate.
  glm::dvec2 centre{0.0};
  // Its extent along its local axes u and v (m), kLocalWaterSizeRange.
  glm::dvec2 size{16.0};
  // Radians about +y, kLocalWaterRotationRange: local u = (cos r, 0, -sin r) and
  // v = (sin r, 0, cos r) in world xyz (r = 0: u = +x, v = +z).
  double rotation = 0.0;
  // GL_TEXTURE_2D covering the rectangle: uv = (local u, v) / size + 0.5, so texel row 0 lies
  // at v = -size.y / 2. RG = slopes (dh/du, dh/dv) along the LOCAL axes, B = height above
  // WaterSurface::level (m; 0 without B); GL_RGBA16F, GL_RGBA32F, GL_RG16F or GL_RG32F, like the
  // cascades. Sampled with clamp-to-edge (the plugin's own sampler, level 0 only: the grid
  // below is the region's resolution). Host-owned, read during dispatch() only.
  TextureRef texture;
  LocalWaterMode mode = LocalWaterMode::Add;
  // Metres inside the rectangle's edge over which its light fades into the cascades'
  // (smoothstep), [0, half the shorter side]. Measured where the light entered the water, so a
  // receiver's weight follows its light, not its own position. 0: a hard edge (a pool whose
  // walls hide it).
  float edgeBlend = 0.5f;
  // Grid cells along the rectangle's longer side (the shorter one in proportion, at least 16),
  // kLocalWaterGridRange: each cell is one ray of the grid refracted onto the receivers, so this
  // is the finest ripple whose caustic the region resolves (report: error against time).
  int gridResolution = 256;
  // Receiver depths the region's light is computed at, kLocalWaterLayerRange, spread
  // quadratically down to maxDepth (m below the level, kLocalWaterDepthRange); a receiver
  // between two layers interpolates them, one deeper than maxDepth takes the deepest. A pool
  // sets maxDepth to its floor's depth: its floor is then exactly on a layer.
  int depthLayers = 4;
  float maxDepth = 4.0f;
};

}  // namespace postfx
