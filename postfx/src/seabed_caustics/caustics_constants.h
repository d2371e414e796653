#pragma once
// Turns a FrameDesc into the seabed caustics' uniform block. Everything that can be far from the
// origin (camera, water level and origin, shadow matrix) is combined here in double and only the
// camera-relative, tile-reduced results become float.
#include <glm/glm.hpp>

#include <postfx/postfx.h>

#include "core/frame_geometry.h"
#include "core/shared_math.h"

namespace postfx::detail {

// The frame uses the WavefrontAreaRatio model (and the context can: Feature::WavefrontAreaRatio).
// Derivative of the sun's landing offset per metre of depth with respect to the water slopes
// (dh/dx, dh/dz) at flat water, column-major 2x2 packed as (d/dsx, d/dsz).
glm::dvec4 landingDriftJacobian(const glm::dvec3& towardSun, double ior);

// Covariance (xx, xz, zz, m^2 per metre^2 of depth) of where light from the sun's disc of
// `angularRadius` radians lands, about where the disc's centre would put it: each direction of
// the disc refracts into its own drift.
glm::dvec3 sunDiscLandingCovariance(const glm::dvec3& towardSun, double ior, double angularRadius);

bool wavefrontAreaRatioActive(const CreateDesc& create, const FrameDesc& frame);

shared::CausticsBlock buildCausticsBlock(const CreateDesc& create, const FrameDesc& frame,
                                         int width, int height, const WaterTextureInfo& water);

}  // namespace postfx::detail
