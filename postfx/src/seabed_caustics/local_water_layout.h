#pragma once
// Where a local water region's grid and irradiance layers lie this frame, in double from its
// LocalWater and the sun: its local frame (a rotation about y), its N x N grid over the rectangle,
// the texture's window (the rectangle and a margin, in entry-point coordinates: a receiver's
// light entered at its local position minus flat water's drift times its depth), the layers'
// depths; and the block the caustics and god-ray passes read it through, per view.
#include <cstdint>

#include <glm/glm.hpp>

#include <postfx/postfx.h>

#include "core/shared_math.h"

namespace postfx::detail {

// The texture spans the rectangle plus this fraction of its side on each side: the refracted
// rays spread sideways with the slopes (1/8 of the side: a pool 8 m wide may throw its light
// 1 m beyond flat water's).
inline constexpr double kLocalWaterMargin = 0.125;

struct LocalWaterLayout {
  int cells = 0;   // grid cells per side over the rectangle (gridResolution)
  int texels = 0;  // the texture's side: cells + 2 margins, one texel per cell
  // cells + 2: at the centres of the rectangle's cells and half a cell beyond each edge (the
  // surface is clamped there)
  int pointsPerSide = 0;
  int layers = 0;       // depth layers
  int fieldLayers = 0;  // the texture's: layers, twice that in Add mode (with and without it)
  bool add = false;
  glm::dvec2 axisU{1.0, 0.0};          // local u in world xz; v = (-u.y, u.x)
  glm::dvec2 half{0.0};                // half the rectangle (m)
  glm::dvec2 cell{0.0};                // grid spacing = texel size along u, v (m)
  glm::dvec2 windowCorner{0.0};        // the texture's corner in entry-point coordinates (local m)
  glm::dvec2 drift{0.0};               // flat water's landing drift per metre of depth (local)
  glm::dvec3 sunLocal{0.0, 1.0, 0.0};  // unit vector toward the sun in local axes (u, y, v)
  double depth[8] = {};
};

// Requires a validated region and a sun above the horizon.
LocalWaterLayout localWaterLayout(const LocalWater& region, const FrameDesc& frame);

// The one texture all of a frame's regions share: the largest region's side, every region's
// layers one after another (region r's in the corner [0, its texels) of each).
struct LocalWaterTexture {
  int side = 0;
  int layers = 0;
  int firstLayer[kMaxLocalWater] = {};
};
LocalWaterTexture localWaterTexture(const FrameDesc& frame);

// The lookups' block for one view (camera-relative centres): count 0 without regions.
shared::LocalWaterBlock buildLocalWaterBlock(const FrameDesc& frame);

// GPU memory of the regions' texture (R32F with its mip levels).
std::uint64_t localWaterTextureBytes(const LocalWaterTexture& texture);
// The largest region's grid points (the buffer is reused by every region and layer).
std::uint64_t localWaterGridPoints(const FrameDesc& frame);
// Everything the frame's regions allocate (0 without regions).
std::uint64_t localWaterBytes(const FrameDesc& frame);

}  // namespace postfx::detail
