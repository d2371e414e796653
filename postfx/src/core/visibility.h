#pragma once
// The CPU tests that let dispatch() skip the caustics passes when they have nothing to do.
#include <glm/glm.hpp>

#include <postfx/conventions.h>

namespace postfx::detail {

// True when some point of the view frustum lies below the water level: the camera is under it,
// or a frustum edge reaches down to it before the far plane (an infinite far plane reaches any
// depth along a downward edge). `levelRelative` = water level - camera y (m). Conservative: a
// true result may still find every pixel above the water, a false one never misses a pixel.
bool frustumReachesBelowWater(const glm::dmat3& viewToWorld, const glm::dmat4& projection,
                              DepthConvention depthConvention, double levelRelative);
// The same above the level: the camera is at or above it, or a frustum edge climbs to it.
bool frustumReachesAboveWater(const glm::dmat3& viewToWorld, const glm::dmat4& projection,
                              DepthConvention depthConvention, double levelRelative);

}  // namespace postfx::detail
