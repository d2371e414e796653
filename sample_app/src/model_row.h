#pragma once
// Where the --model files without a position go: in a row across the preset's view, so that
// every preset shows them (a fixed row at z = 5 stood where the default preset's camera does not
// look, and `render --model X.glb` gave the image it gave without it).

#include <cstddef>

#include <glm/glm.hpp>

#include "camera.h"

namespace ocean {

// The position (model_spec.h's: x, z of the box's centre, y the height of its bottom above the
// sand) of model `index` of `count` whose placed box is `height` m tall: along the camera's
// centre ray, 0.7 of the way to where it meets the sand (2.5 to 12 m ahead; 6 m when it meets
// no sand within 40 m), spaced across the view so the row fits its width, resting on the sand
// or, where the ray passes above it, centred on the ray and kept under the water.
glm::dvec3 rowPosition(const Camera& camera, std::size_t index, std::size_t count, double height,
                       double (*sandHeight)(double x, double z));

}  // namespace ocean
