#pragma once
// The CPU test that lets dispatch() skip the caustics pass when it has nothing to do.
#include <glm/glm.hpp>

#include <postfx/conventions.h>

namespace postfx::detail {

// True when some point of the view frustum lies below the water level: the camera is under it,
// or a frustum edge reaches down to it before the far plane (an infinite far plane reaches any
// depth along a downward edge). `levelRelative` = water level - camera y (m). Conservative: a
// true result may still find every pixel above the water, a false one never misses a pixel.
bool frustumReachesBelowWater(const glm::dmat3& viewToWorld, const glm::dmat4& projection,
                              DepthConvention depthConvention, double levelRelative);

}  // namespace postfx::detail
