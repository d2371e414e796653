#pragma once
// Turns a FrameDesc into the caustics pass's uniform block. Everything that can be far from the
// origin (camera, water level and origin, shadow matrix) is combined here in double and only the
// camera-relative, tile-reduced results become float.
#include <glm/glm.hpp>

#include <postfx/postfx.h>

#include "core/shared_math.h"

namespace postfx::detail {

// Size and mip count of the water texture, from validation.
struct WaterTextureInfo {
  int width = 1;
  int height = 1;
};

// The frame uses the WavefrontAreaRatio model (and the context can: Feature::PhysicalCaustics).
// Derivative of the sun's landing offset per metre of depth with respect to the water slopes
// (dh/dx, dh/dz) at flat water, column-major 2x2 packed as (d/dsx, d/dsz).
glm::dvec4 landingDriftJacobian(const glm::dvec3& towardSun, double ior);

// Covariance (xx, xz, zz, m^2 per metre^2 of depth) of where light from the sun's disc of
// `angularRadius` radians lands, about where the disc's centre would put it: each direction of
// the disc refracts into its own drift.
glm::dvec3 sunDiscLandingCovariance(const glm::dvec3& towardSun, double ior, double angularRadius);

bool physicalCausticsActive(const CreateDesc& create, const FrameDesc& frame);

shared::CausticsBlock buildCausticsBlock(const CreateDesc& create, const FrameDesc& frame,
                                         int width, int height, const WaterTextureInfo& water);

// x - floor(x / period) * period, divided by period: the fraction of a tile, in [0, 1).
double tileFraction(double metres, double period);

// The sun ray refracted through flat water (pointing down), eta = 1 / IOR.
glm::dvec3 refractedSunDown(const glm::dvec3& towardSun, double ior);

// Unit vector perpendicular to the plane of incidence (vertical plane containing the sun); the
// seed's reference vector for both unperturbed rays. World x for a sun at the zenith.
glm::dvec3 incidencePlaneNormal(const glm::dvec3& towardSun);

// World-to-view rotation part of the camera's view matrix, transposed: view -> world.
glm::dmat3 viewToWorldRotation(const glm::mat4& view);

}  // namespace postfx::detail
