#version 450 core
#include "shared/gbuffer_codec.h"
#include "sample/rock_detail.glsl"
in vec3 worldNormal;
in vec3 relativePosition;  // camera-relative world (m)
uniform vec3 albedo;
// 1 for the sample's rock and stone: procedural colour and bumps (rock_detail.glsl); 0 draws
// the material's flat colour, as a glTF model without textures asks.
uniform float surfaceDetail;
uniform vec3 cameraWorld;  // m: the noise is fixed to the world, not to the view
// A tiled surface's joints: x = pitch (m, 0: none), y = half the joint's width (m).
uniform vec2 tileJoints;
layout(location = 0) out vec2 outNormal;  // RG16_SNORM octahedral
layout(location = 1) out vec4 outAlbedo;  // SRGB8_ALPHA8
// The integral from 0 to x of the joints' pulse train (1 within `halfWidth` of a multiple of
// `pitch`): differences of it box-filter the joints over a pixel.
float jointIntegral(float x, float pitch, float halfWidth) {
  float cell = floor(x / pitch + 0.5);
  return cell * 2.0 * halfWidth + clamp(x - cell * pitch, -halfWidth, halfWidth);
}

// The share of a pixel `footprint` wide around x that lies on a joint.
float jointShare(float x, float footprint, float pitch, float halfWidth) {
  float f = max(footprint, 1e-5);
  return clamp((jointIntegral(x + 0.5 * f, pitch, halfWidth) -
                jointIntegral(x - 0.5 * f, pitch, halfWidth)) / f, 0.0, 1.0);
}

// How much of the pixel is grout, on the plane the normal is closest to facing.
float groutShare(vec3 world, vec3 n) {
  vec3 a = abs(n);
  vec2 p = a.y >= a.x && a.y >= a.z ? world.xz : (a.x >= a.z ? world.yz : world.xy);
  vec2 footprint = fwidth(p);
  float u = jointShare(p.x, footprint.x, tileJoints.x, tileJoints.y);
  float v = jointShare(p.y, footprint.y, tileJoints.x, tileJoints.y);
  return 1.0 - (1.0 - u) * (1.0 - v);
}

void main() {
  vec3 n = safeNormalize(worldNormal);
  if (!gl_FrontFacing) n = -n;  // double-sided geometry: shade the side we see
  vec3 colour = albedo;
  if (surfaceDetail > 0.5) {
    // The pixel's footprint in metres: octaves finer than two of it are left out (no shimmer).
    const float footprint = max(length(fwidth(relativePosition)), 1e-4);
    rockDetail(relativePosition + cameraWorld, footprint, n, colour);
  }
  // Grout is 0.4 of the tile's albedo (grey joints between white tiles, darker between slabs).
  if (tileJoints.x > 0.0)
    colour *= 1.0 - 0.6 * groutShare(relativePosition + cameraWorld, n);
  outNormal = octEncode(n);
  outAlbedo = vec4(colour, 1.0);
}
