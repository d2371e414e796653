#version 450 core
// Glass, drawn forward over the lit, fogged frame after the plugin. The G-buffer has no glass,
// so the frame holds what lies behind it, caustics included: this pixel shows the Fresnel
// reflection of the environment and the sun, and the frame refracted through both surfaces
// (the far one from glass_back_faces.frag), absorbed inside (Beer-Lambert).
#include "shared/gbuffer_codec.h"
#include "shared/sample_frame.h"
#include "shared/sample_optics.h"
#include "sample/reconstruct.glsl"
#include "sample/water_column.glsl"
#include "sample/environment.glsl"
#include "sample/sun_shadow.glsl"
in vec3 worldNormal;
in vec3 relativePosition;
uniform float materialIor;
uniform float roughness;
uniform vec3 glassAbsorption;  // 1/m
layout(binding = 0) uniform sampler2D sceneColour;  // the fogged frame before the glass
layout(binding = 1) uniform sampler2D sceneDepth;   // the G-buffer's depth: no glass in it
layout(binding = 2) uniform sampler2D backFaces;    // glass_back_faces.frag's output
layout(binding = 3) uniform sampler2DShadow shadowMap;
out vec4 outColor;

// The pixel a camera-relative point (w = 1) or a direction's vanishing point (w = 0)
// projects to; false off screen or behind the camera.
bool clipToScreen(vec4 clip, out ivec2 pixel) {
  if (!(clip.w > 1e-4)) return false;
  vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
  if (any(lessThan(uv, vec2(0.0))) || any(greaterThanEqual(uv, vec2(1.0)))) return false;
  pixel = ivec2(uv * vec2(textureSize(sceneDepth, 0)));
  return true;
}

bool toScreen(vec3 relative, out ivec2 pixel) {
  return clipToScreen(viewProjection * vec4(relative, 1.0), pixel);
}

const int kOffScreen = -1, kInFront = 0, kBehind = 1;
// Where the point lies against what the frame shows at its pixel.
int againstScene(vec3 p, out ivec2 pixel) {
  if (!toScreen(p, pixel)) return kOffScreen;
  float depth = texelFetch(sceneDepth, pixel, 0).r;
  if (isSkyDepth(depth, int(projectionZ.z))) return kInFront;
  vec2 uv = (vec2(pixel) + 0.5) / vec2(textureSize(sceneDepth, 0));
  return length(p) >= length(reconstructRelative(uv, depth)) ? kBehind : kInFront;
}

// What the ray from `origin` along `dir` meets in the frame: marched in screen space against
// the G-buffer's depth in growing steps, the crossing refined by bisection. Where the ray
// meets nothing the frame holds, the water column or sky the frame shows along that direction
// (at its vanishing point, fog and god rays included); where that is off screen too, the
// environment, seen through the water to the camera (the glass's own view fog).
vec3 sceneAlong(vec3 origin, vec3 dir, float height, vec3 transmittance, vec3 inscatter) {
  float previous = 0.0, t = 0.03;
  ivec2 pixel;
  int where = kInFront;
  for (int i = 0; i < 28; ++i) {
    where = againstScene(origin + dir * t, pixel);
    if (where == kOffScreen) break;
    if (where == kBehind) {
      for (int j = 0; j < 5; ++j) {
        float middle = 0.5 * (previous + t);
        ivec2 at;
        if (againstScene(origin + dir * middle, at) == kBehind) {
          t = middle;
          pixel = at;
        } else {
          previous = middle;
        }
      }
      return texelFetch(sceneColour, pixel, 0).rgb;
    }
    previous = t;
    t *= 1.3;
  }
  // Still in front of everything after the march (tens of metres): toward open water or
  // something as far, whose light depends on the direction alone, as the frame's own pixel
  // along that direction shows it.
  if (where != kOffScreen && clipToScreen(viewProjection * vec4(dir, 0.0), pixel)) {
    float depth = texelFetch(sceneDepth, pixel, 0).r;
    vec2 uv = (vec2(pixel) + 0.5) / vec2(textureSize(sceneDepth, 0));
    if (isSkyDepth(depth, int(projectionZ.z)) ||
        length(reconstructRelative(uv, depth)) > 0.5 * t)
      return texelFetch(sceneColour, pixel, 0).rgb;
  }
  return environmentRadiance(dir, height) * transmittance + inscatter;
}

void main() {
  vec3 n = normalize(worldNormal);
  vec3 v = normalize(relativePosition);
  if (dot(n, v) >= 0.0) discard;  // a far side: glass_back_faces.frag has it
  float height = cameraHeight.x + relativePosition.y;
  float outside = height < 0.0 ? waterParams.x : 1.0;  // the medium around the glass
  float fFront = fresnelReflectance(-dot(v, n), outside, materialIor);
  vec3 transmittance, inscatter;
  viewFog(relativePosition, transmittance, inscatter);

  vec3 inside = refract(v, n, outside / materialIor);
  vec4 back = texelFetch(backFaces, ivec2(gl_FragCoord.xy), 0);
  vec3 transmitted;
  if (back.w <= 0.0) {
    // An open sheet: thin glass.
    transmitted = sceneAlong(relativePosition, v, height, transmittance, inscatter);
  } else {
    // Wyman's estimate of the path inside: the far side's distance along the view, less ours.
    float thickness = max(back.w - length(relativePosition), 0.0);
    vec3 exitPoint = relativePosition + inside * thickness;
    ivec2 exitPixel;
    vec4 exitBack = toScreen(exitPoint, exitPixel) ? texelFetch(backFaces, exitPixel, 0) : back;
    vec3 nBack = exitBack.w > 0.0 ? exitBack.xyz : back.xyz;  // outward
    vec3 leaving = refract(inside, -nBack, materialIor / outside);
    float fBack = fresnelReflectance(max(dot(inside, nBack), 0.0), materialIor, outside);
    // Total internal reflection: the light that reaches us there came in elsewhere; the
    // mirrored ray stands in for that path.
    if (fBack >= 1.0 || dot(leaving, leaving) < 0.5) {
      leaving = reflect(inside, -nBack);
      fBack = 0.0;
    }
    transmitted = sceneAlong(exitPoint, leaving, height, transmittance, inscatter) * (1.0 - fBack) *
                  exp(-glassAbsorption * thickness);
  }

  float f0 = pow((materialIor - outside) / (materialIor + outside), 2.0);
  vec3 reflected = environmentRadiance(reflect(v, n), height) * fFront +
                   sunSpecular(n, v, vec3(f0), roughness, height,
                               sunShadow(shadowMap, relativePosition, n));
  outColor = vec4(reflected * transmittance + inscatter * fFront + transmitted * (1.0 - fFront),
                  1.0);
}
