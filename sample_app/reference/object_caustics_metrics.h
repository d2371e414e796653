#pragma once
// Measurements on the plugin's object caustic map (postfx::objectCausticMap) and on the CPU
// reference binned the same way: read-back, total flux, the focus (brightest spot) and where a
// texel lands on the receiver plane, and the resampling of a map onto a fixed grid of bins so
// that maps of any size and placement are compared with one converged reference.
#include <glm/glm.hpp>
#include <vector>

#include <postfx/postfx.h>

namespace ocean::reference {

// The plugin's map read back as doubles (rgb), size x size, row v = 0 first.
std::vector<glm::dvec3> readObjectMap(const postfx::ObjectCausticMap& map);

// Total flux (sun irradiance 1, m^2) in a map of relative irradiance.
glm::dvec3 mapFlux(const std::vector<glm::dvec3>& map, const postfx::ObjectCausticMap& placement);

// Brightest spot: centroid (texel units, continuous) of the texels >= half the maximum of the
// green channel within +-radius texels of the maximum.
glm::dvec2 focusTexel(const std::vector<glm::dvec3>& map, int size, int radius = 6);

// Where the map texel position lies on the plane y = planeY (projected along the light).
glm::dvec3 texelOnPlane(const postfx::ObjectCausticMap& map, const glm::dvec2& texel,
                        double planeY);

// A square grid of `count` x `count` bins of side `side` / count (m), perpendicular to the light
// and with the axes of `like` (a map of the same light), centred on the light's line through
// `centre`. Given as a map placement, so traceSphereReference bins into it directly.
postfx::ObjectCausticMap binGrid(const postfx::ObjectCausticMap& like, const glm::dvec3& centre,
                                 double side, int count);

// Mean of one channel of `map` (placed by `placement`) over each bin of `bins` (from binGrid with
// the same light), every texel taken as constant over its square: exact for maps whose texels
// do not line up with the bins. Bins the map does not cover count the missing part as 0.
std::vector<double> resampleToBins(const std::vector<glm::dvec3>& map,
                                   const postfx::ObjectCausticMap& placement,
                                   const postfx::ObjectCausticMap& bins, int channel = 1);

}  // namespace ocean::reference
