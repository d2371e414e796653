#pragma once
// Where a pixel's view ray meets the water's mean plane: the view's click on the pool drops
// water there.
#include <glm/glm.hpp>

#include "camera.h"

namespace ocean {

// `ndc` in [-1, 1]^2 (x right, y up) of a view of `aspect` (width / height); `level` the
// water's height (m). The world x, z of the hit; false when the ray runs parallel to the plane,
// away from it, or meets it more than 1e5 m away.
bool pickWaterPlane(const Camera& camera, double aspect, glm::dvec2 ndc, double level,
                    glm::dvec2& worldXZ);

}  // namespace ocean
