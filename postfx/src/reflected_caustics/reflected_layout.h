#pragma once
// Where the reflected light field lies this frame, computed in double from the FrameDesc: the
// receiver window (ahead of the camera, snapped to whole texels of its coarsest filtered level so
// the pattern does not swim), each height layer's water grid (snapped to whole cells, moved against
// the mirror ray's drift so its light lands in the window) and the layers' heights.
#include <cstdint>

#include <glm/glm.hpp>

#include <postfx/postfx.h>

namespace postfx::detail {

inline constexpr int kMaxReflectedLayers = 8;
// How far ahead of the camera the window's centre lies, along the view's horizontal direction,
// in window sides (a quarter of the window stays behind the camera).
inline constexpr double kReflectedWindowAhead = 0.25;
// The field's channels per height layer: the light, and its drift-weighted x and z sums.
inline constexpr int kReflectedChannels = 3;

struct ReflectedLayout {
  int resolution = 0;  // texels and grid cells' nominal count per side
  int layers = 0;
  double windowSize = 0.0, texel = 0.0;
  glm::dvec2 windowOrigin{0.0};  // world xz of texel (0, 0)'s corner
  double cell = 0.0;             // grid spacing (m)
  int cells = 0;                 // grid cells per side (resolution + 1: snapping headroom)
  double height[kMaxReflectedLayers] = {};
  glm::dvec2 gridOrigin[kMaxReflectedLayers] = {};  // world xz of grid vertex (0, 0)
  // The flat mirror ray's horizontal drift per metre of height: -towardSun.xz / towardSun.y.
  glm::dvec2 rise{0.0};
  // The layers are blurred by the landing spread of the slopes finer than a cell
  // (CausticsSettings::tileUnresolvedSpread) and of the sun's disc (Sun::angularDiameterDegrees),
  // as the refracted window's are.
  bool spread = false;
};

// Derivative of the mirrored sun's landing offset per metre of height with respect to the
// water slopes (dh/dx, dh/dz) at flat water, packed as landingDriftJacobian's: a mirror turns
// the ray by twice the slope, so it is about 2 / sin^2(elevation) along the sun's azimuth.
glm::dvec4 reflectedLandingJacobian(const glm::dvec3& towardSun);
// Covariance (xx, xz, zz, m^2 per metre^2 of height) of where light from the sun's disc of
// `angularRadius` radians lands after a flat mirror, about where its centre's would.
glm::dvec3 reflectedSunDiscCovariance(const glm::dvec3& towardSun, double angularRadius);

// Height of layer k of `layers` (m above the level): denser near the water, where short waves
// focus their light.
double reflectedLayerHeight(int k, int layers, double maxHeight);

// Requires validated settings and a sun above the horizon.
ReflectedLayout reflectedLayout(const FrameDesc& frame);

// GPU memory the field allocates for `gridResolution` and `layers`: the R32F layers of its three
// channels with their mip levels and the grid points (two vec4 per point); with `spread`, the
// blur's copy of one channel's level 0 and the slope statistics. The memory estimate and
// ReflectedFieldPass::allocatedBytes() must agree (a test checks).
std::uint64_t reflectedFieldBytes(int gridResolution, int layers, bool spread);
// GPU memory ReflectedLanding::ViewDepth allocates: the grid points (two vec4 per point), an
// RG32F light target of the G-buffer's size and, with `slopeSpread`
// (CausticsSettings::tileUnresolvedSpread), the slope statistics
// (ReflectedReceiverPass::allocatedBytes()).
std::uint64_t reflectedReceiverBytes(int gridResolution, int targetWidth, int targetHeight,
                                     bool slopeSpread);

}  // namespace postfx::detail
