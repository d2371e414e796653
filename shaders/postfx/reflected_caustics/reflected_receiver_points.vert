#version 450 core
// Reflected caustics landing on the view's depth, step 3 of 3: up to three points per grid
// triangle (vertex 3 t + k), for the light the triangle draw leaves: a focused triangle landed
// whole on under splat.z pixels^2 (landsAsPoint) deposits its flux at its centre (corner 0), one
// broken across
// surfaces or partly lost each corner's third at that corner's own hit; split over the four
// nearest pixels by bilinear weights, so that light focused below a pixel is neither lost
// between pixel centres nor flickers from one to the next.
#include "shared/common.h"
#include "postfx/seabed_caustics/postfx_caustics_block.h"
#include "postfx/reflected_caustics/reflected_receiver_common.glsl"

flat out vec3 position;
flat out float pointFlux;
flat out vec2 landing;
flat out vec3 receiverNormal;
flat out float spreadVariance;
// > 0: the point is a disc of this radius (m) on its receiver (Epanechnikov, as the trace's
// kernel); 0: the bilinear four-pixel point.
flat out float kernelRadius;

float cross2(vec2 a, vec2 b) {
  return a.x * b.y - a.y * b.x;
}

void main() {
  int k = gl_VertexID % 3;
  GridTriangle t = gridTriangle(gl_VertexID / 3);
  float flux, area;
  bool whole = landedWhole(t, flux, area, receiverNormal);
  vec2 s0 = viewPixels(t.hit[0].xyz), s1 = viewPixels(t.hit[1].xyz), s2 = viewPixels(t.hit[2].xyz);
  float pixels = 0.5 * abs(cross2(s1 - s0, s2 - s0));
  gl_PointSize = 4.0;
  position = vec3(0.0);
  pointFlux = 0.0;
  landing = vec2(0.0);
  kernelRadius = 0.0;
  spreadVariance = 0.0;
  if (whole && flux > 0.0 && pixels >= 0.0 &&
      (!(area > 0.0) || landsAsPoint(pixels, flux / area, receiverNormal)) && k == 0) {
    // Landed whole on under a pixel: its flux at its centre.
    position = (t.hit[0].xyz + t.hit[1].xyz + t.hit[2].xyz) * (1.0 / 3.0);
    pointFlux = flux;
    landing = (s0 + s1 + s2) * (1.0 / 3.0);
    spreadVariance = (t.spread[0] + t.spread[1] + t.spread[2]) * (1.0 / 3.0);
  } else if (!whole && t.hit[k].w > 0.0 && min(min(t.hit[0].w, t.hit[1].w), t.hit[2].w) > -1.5) {
    // Broken across surfaces or partly lost (to the sky): each corner's third where its own ray
    // landed. Not when a corner's ray left the view: most of its light may have too, and its
    // thirds would brighten the frame's edges.
    position = t.hit[k].xyz;
    receiverNormal = t.normal[k];
    spreadVariance = t.spread[k];
    pointFlux = splat.x * t.hit[k].w * (1.0 / 3.0);
    landing = viewPixels(position);
    // Its third of the triangle's light lands, in the aggregate of the folds, over the reach
    // of the corners around it: a disc of half the longest edge from it (at least a pixel).
    float reach = 0.0;
    for (int j = 0; j < 3; ++j)
      if (j != k && t.hit[j].w >= 0.0) reach = max(reach, distance(t.hit[j].xyz, position));
    float pixelSize = length(position) * u.depthAndWater.w;
    kernelRadius = clamp(0.5 * reach, pixelSize, 16.0 * pixelSize);
    gl_PointSize = 2.0 * ceil(kernelRadius / pixelSize) + 2.0;
  }
  if (!(pointFlux > 0.0) || !all(lessThan(abs(landing), vec2(1e6)))) {
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
    return;
  }
  gl_Position = vec4(landing * 2.0 * u.viewport.xy - 1.0, 0.0, 1.0);
}
