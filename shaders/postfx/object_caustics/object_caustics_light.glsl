// Where the light comes from, for every object-caustics shader: the sun's parallel rays, or a
// local light's rays spreading from its position. Positions are anchor-relative.
#ifndef POSTFX_OBJECT_CAUSTICS_LIGHT_GLSL
#define POSTFX_OBJECT_CAUSTICS_LIGHT_GLSL
#include "shared/common.h"
#include "postfx/object_caustics/postfx_object_caustics_block.h"

bool localLight() {
  return u.lightPosition.w > 0.5;
}

// Unit direction the light travels at p: the sun's everywhere, a local light's away from it (its
// view's axis at the light itself, where there is no direction).
vec3 lightRayAt(vec3 p) {
  if (!localLight()) return u.lightDir.xyz;
  vec3 d = p - u.lightPosition.xyz;
  float len2 = dot(d, d);
  return len2 > 1e-30 ? d * inversesqrt(len2) : u.lightDir.xyz;
}

// p seen through one of the light's views (casterClip, mapClip), in [0, 1]^2 over the view.
// False behind a local light (the sun's views are orthographic: never).
bool viewUv(mat4 viewClip, vec3 p, out vec2 uv) {
  vec4 clip = viewClip * vec4(p, 1.0);
  uv = vec2(-1.0);
  if (!(clip.w > 0.0)) return false;
  uv = clip.xy / clip.w * 0.5 + 0.5;
  return true;
}

#endif
