#version 450 core
// Reflected caustics landing on the view's depth, step 2 of 3: the mirrored grid as triangles on
// the receivers (vertex 3 t + k is corner k of grid triangle t), each carrying its flux over the
// area it landed on: the light it brings there, folds summed by the blend. Triangles under
// landsAsPoint go to the point draw (reflected_receiver_points.vert) instead.
#include "shared/common.h"
#include "postfx/seabed_caustics/postfx_caustics_block.h"
#include "postfx/reflected_caustics/reflected_receiver_common.glsl"

smooth out vec3 position;
flat out float irradiance;
flat out vec3 receiverNormal;
flat out float spreadVariance;

float cross2(vec2 a, vec2 b) {
  return a.x * b.y - a.y * b.x;
}

void main() {
  GridTriangle t = gridTriangle(gl_VertexID / 3);
  float flux, area;
  bool whole = landedWhole(t, flux, area, receiverNormal);
  vec2 s0 = viewPixels(t.hit[0].xyz), s1 = viewPixels(t.hit[1].xyz), s2 = viewPixels(t.hit[2].xyz);
  float pixels = 0.5 * abs(cross2(s1 - s0, s2 - s0));
  if (!whole || !(area > 0.0) || !(flux > 0.0) || !(pixels >= 0.0) ||
      landsAsPoint(pixels, flux / area, receiverNormal)) {
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);  // outside the clip volume
    position = vec3(0.0);
    irradiance = 0.0;
    spreadVariance = 0.0;
    return;
  }
  irradiance = min(flux / area, splat.y);
  spreadVariance = (t.spread[0] + t.spread[1] + t.spread[2]) * (1.0 / 3.0);
  position = t.hit[gl_VertexID % 3].xyz;
  gl_Position = viewClip(position);
}
