// The water under a grid's point: every cascade's slopes and height summed, each read at the mip
// matching a grid cell (the refracted window's wavefront_area_ratio_vertices.comp, the reflected
// light's reflected_light_vertices.comp and reflected_receiver_rays.comp). Declares the water
// texture and the cascades' uniforms (locations 0 to 4).
#include "postfx/seabed_caustics/water_texture.glsl"

// Per cascade: xy = uv of grid point (0, 0) (reduced modulo the tile in double), z = uv per grid
// cell, w = mip level matching the grid spacing (what the grid cannot carry is low-passed away
// rather than aliased into false lines).
layout(location = 0) uniform vec4 cascadeGrid[POSTFX_MAX_CASCADES];
layout(location = 4) uniform int cascadeCount;

// Slopes (xy) and height (z) of the water at grid point `index`.
vec3 gridWater(ivec2 index) {
  vec3 surface = vec3(0.0);
  for (int c = 0; c < POSTFX_MAX_CASCADES; ++c) {
    if (c >= cascadeCount) break;
    vec2 uv = cascadeGrid[c].xy + vec2(index) * cascadeGrid[c].z;
    surface += textureLod(waterSurface, WATER_COORD(uv, c), cascadeGrid[c].w).rgb;
  }
  return surface;
}
