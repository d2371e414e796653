#include "god_rays/godrays_constants.h"

#include <algorithm>
#include <cmath>

#include "core/frame_geometry.h"
#include "core/shared_math.h"

static_assert(postfx::shared::GODRAYS_MAX_SAMPLES == postfx::kGodRaySampleCountRange.max,
              "the march's loop bound is the most samples a frame may ask for");

namespace postfx::detail {

GodRayGrid godRayGrid(const glm::dvec3& towardSun, double ior) {
  GodRayGrid grid;
  const glm::dvec3 sun = glm::normalize(towardSun);
  grid.y = -refractedSunDown(sun, ior);
  // The plane-of-incidence normal is horizontal and perpendicular to the refracted ray (which
  // lies in that plane), so it is already orthogonal to y.
  grid.x = incidencePlaneNormal(sun);
  grid.z = glm::normalize(glm::cross(grid.x, grid.y));
  return grid;
}

double godRayGridPhase(double value, double spacing) {
  const double phase = value - std::floor(value / spacing) * spacing;
  return phase >= spacing || phase < 0.0 ? 0.0 : phase;  // rounding can land on the bound
}

const glm::dvec3& GodRayGridPivot::follow(const GodRayGrid& grid, double spacing,
                                          const glm::dvec3& camera) {
  const bool sameSpacing = spacing_ > 0.0 && spacing == spacing_;
  // The same sun through a different length (or rounding) gives axes a few ulps apart: the same
  // grid, whose lattice still passes through the anchor.
  const bool sameGrid = sameSpacing && glm::length(grid.x - grid_.x) <= kSameGrid &&
                        glm::length(grid.y - grid_.y) <= kSameGrid;
  if (sameGrid) {
    grid_ = grid;
  } else {
    const double cosTurn = std::cos(kMaxContinuousTurn);
    const bool continuous =
        sameSpacing && glm::dot(grid.x, grid_.x) >= cosTurn && glm::dot(grid.y, grid_.y) >= cosTurn;
    // Near the origin, turning about the origin moves nearby planes as little as turning about
    // the camera would: the anchor stays there, as in a fresh context, until the camera is far.
    const bool atOrigin =
        anchor_ == glm::dvec3(0.0) && glm::length(pivot_) <= kOriginReach * spacing;
    anchor_ = continuous && !atOrigin ? pivot_ : glm::dvec3(0.0);
    grid_ = grid;
    spacing_ = spacing;
  }
  const glm::dvec3 d = camera - anchor_;
  pivot_ = anchor_ + std::round(glm::dot(d, grid.x) / spacing) * spacing * grid.x +
           std::round(glm::dot(d, grid.z) / spacing) * spacing * grid.z +
           glm::dot(d, grid.y) * grid.y;
  return pivot_;
}

shared::GodRaysBlock buildGodRaysBlock(const FrameDesc& frame, int width, int height,
                                       GodRayGridPivot& pivot, bool uniformSampling,
                                       float uniformPhase) {
  shared::GodRaysBlock b{};
  const GodRaySettings& s = frame.godRays;
  const WaterSurface& water = frame.water;
  const GodRayGrid grid = godRayGrid(frame.sun.direction, water.ior);
  const double spacing = s.gridSpacing;
  b.gridX = glm::vec4(glm::vec3(grid.x), s.gridSpacing);
  b.gridZ = glm::vec4(glm::vec3(grid.z), static_cast<float>(s.sampleCount));
  // World snapping: the grid's planes pass through the pivot (the world origin until the camera
  // moves); only the camera's offset within its cell reaches the GPU.
  const glm::dvec3 camera =
      frame.camera.position - pivot.follow(grid, spacing, frame.camera.position);
  b.gridOffset = glm::vec4(static_cast<float>(godRayGridPhase(glm::dot(camera, grid.x), spacing)),
                           static_cast<float>(godRayGridPhase(glm::dot(camera, grid.z), spacing)),
                           uniformSampling ? 1.0f : 0.0f, s.dither ? 1.0f : 0.0f);
  b.fade = glm::vec4(s.surfaceFadeDistance, s.depthFadeDistance, s.maxDistance, uniformPhase);
  const glm::dvec3 extinction = glm::dvec3(water.absorption) + glm::dvec3(water.scattering);
  b.extinction = glm::vec4(glm::vec3(extinction), 0.0f);
  // grid.y.y >= cos(critical angle) ~ 0.66 for a sun above the horizon (the pass is skipped
  // otherwise): no division by ~0.
  b.sunPath = glm::vec4(glm::vec3(extinction / std::max(grid.y.y, 1e-3)), 0.0f);
  b.lightScale = glm::vec4(frame.sun.irradiance * s.intensity, 0.0f);
  b.scattering = glm::vec4(water.scattering, 0.0f);
  const int reducedWidth = godRayReducedSize(width, s.resolution);
  const int reducedHeight = godRayReducedSize(height, s.resolution);
  b.reducedViewport =
      glm::vec4(1.0f / static_cast<float>(reducedWidth), 1.0f / static_cast<float>(reducedHeight),
                static_cast<float>(reducedWidth), static_cast<float>(reducedHeight));
  const int k = static_cast<int>(s.resolution);
  b.reduction = glm::vec4(static_cast<float>(k), 0.0f, 0.0f, 0.0f);
  return b;
}

}  // namespace postfx::detail
