#pragma once
// A point or spot light's caustic map from the plugin (postfx::testing::lightCausticMap: caustic
// irradiance per unit intensity on a surface facing the light, texels in the light's
// perspective view) placed on a receiver plane, so that it meets the reference
// (traceSphereFromLight) in the same bins: each texel's flux, E r^2 times its solid angle, goes
// to the bins where its directions meet the plane.
#include <glm/glm.hpp>
#include <vector>

#include "object_caustics_local_light.h"

namespace ocean::reference {

struct LightMapOnPlane {
  std::vector<glm::dvec3> irradiance;  // per bin, per unit intensity (1/m^2)
  glm::dvec3 fluxInBins{0.0};          // per unit intensity (sr)
  glm::dvec3 fluxOutside{0.0};         // landed on the plane outside the bins
  glm::dvec3 fluxMissing{0.0};         // texels whose direction never meets the plane
};

// `map`: size x size texels (row 0 first, as readObjectMap returns them); `worldToMapClip`: world
// -> the map's clip space (a texel's centre at ((c.xy / c.w) * 0.5 + 0.5) * size); `light`: the
// light's position. Each texel is split into subsamples^2 parts, each sent to its own bin.
LightMapOnPlane lightMapOnBins(const std::vector<glm::dvec3>& map, int size,
                               const glm::dmat4& worldToMapClip, const glm::dvec3& light,
                               const ReceiverBins& bins, int subsamples = 4);

// Flux-weighted centroid (green channel) of a map of bins, in bin units.
glm::dvec2 binCentroid(const std::vector<glm::dvec3>& irradiance, int size);

}  // namespace ocean::reference
