#version 450 core
// The light one ray scatters toward the camera at this pixel (casters.h, VolumeCausticsSettings):
// the view ray's closest approach to the ray's segment, its distance b from it and their angle
// theta give L = P * k(b) / sin(theta) * T_light * T_view * rho (P's sigma_s, phase and light
// scale in u.volumeLight), k the 1D kernel: the beam's Gaussian cross-section projected across
// the view ray (plus the pixel's footprint), or a one-pixel box for lines. Depth-tested against
// the G-buffer: a ray behind what the pixel sees adds nothing. Summed in float (a texture of the
// view's size, its lower-left pixel at the view's: thousands of rays each add less than a half
// float's step to a bright target) and added to the target like the god rays.
#include "shared/common.h"
#include "postfx/common/postfx_bindings.h"
#include "shared/gbuffer_codec.h"
#include "postfx/seabed_caustics/postfx_caustics.h"
#include "postfx/god_rays/postfx_godrays.h"
#include "postfx/object_caustics/postfx_object_caustics.h"
#include "postfx/object_caustics/postfx_object_caustics_block.h"
#include "postfx/object_caustics/volume_caustics_common.glsl"

layout(binding = POSTFX_UNIT_DEPTH) uniform sampler2D gbufferDepth;

flat in vec3 beamStart;
flat in vec3 beamEnd;
flat in vec3 beamPower;
flat in float beamLightPath;
flat in vec3 axisX0, axisY0, axisX1, axisY1;
flat in float lineSlant;

layout(location = 0) out vec4 outLight;

const float kInvSqrtTwoPi = 0.39894228;
const float kWithinThreeSigma = 0.99730020;  // erf(3 / sqrt 2): the 1D Gaussian within 3 sigma

void main() {
  vec2 uv = gl_FragCoord.xy * u.viewport.xy;  // gl_FragCoord: in the view
  vec2 ndc = uv * 2.0 - 1.0;
  vec3 viewDir = normalize(vec3((ndc.x + u.projection.z) / u.projection.x,
                                (ndc.y + u.projection.w) / u.projection.y, -1.0));
  vec3 d = mat3(u.viewToWorld) * viewDir;  // camera-relative world, unit
  vec3 e = beamEnd - beamStart;
  float len = length(e);
  if (!(len > 1e-6)) discard;
  e /= len;
  // Closest approach of t * d (the view ray) and beamStart + s * e.
  float c = dot(d, e);
  float sin2 = 1.0 - c * c;
  if (!(sin2 > 1e-8)) discard;  // the ray runs along the view ray: no extent to scatter over
  float pd = dot(beamStart, d), pe = dot(beamStart, e);
  float t = (pd - c * pe) / sin2;
  float s = (c * pd - pe) / sin2;
  if (!(s >= 0.0 && s <= len && t > 0.0 && t <= u.volumeFade.z)) discard;
  vec3 onRay = beamStart + s * e;
  // Depth test: only light scattered in front of the surface the pixel sees (the ray's point,
  // not the view ray's: a wide beam's kernel reaches pixels whose closest approach to it lies
  // in front of a wall the ray itself runs behind).
  float depth = texelFetch(gbufferDepth, ivec2(gl_FragCoord.xy + u.viewOrigin.xy), 0).r;
  if (!isSkyDepth(depth, POSTFX_DEPTH_CONVENTION)) {
    vec3 surface = viewPositionFromDepth(uv, depth, u.projection, u.depthParams.xy,
                                         POSTFX_DEPTH_CONVENTION);
    if (!(max(t, dot(onRay, d)) <= length(surface))) discard;
  }
  vec3 offset = t * d - onRay;
  float b2 = dot(offset, offset);
  float footprint = t * u.volumePixel.x;  // the pixel's width at the ray (m)
#if POSTFX_VOLUME_LINES
  // A one-pixel box across the line. The raster gives one fragment per major-axis step, whose
  // pixels lie 1 / lineSlant apart across the line: each fragment stands for lineSlant of them.
  float kernel = lineSlant / footprint;
#else
  // The cross-section's spread across the view ray: along n, perpendicular to both.
  vec3 n = cross(d, e) * inversesqrt(sin2);
  float f = s / len;
  vec3 ax = mix(axisX0, axisX1, f), ay = mix(axisY0, axisY1, f);
  float nx = dot(n, ax), ny = dot(n, ay);
  // The pixel's own footprint as a box's variance (w^2 / 12) keeps a beam narrower than a pixel
  // from aliasing.
  float variance = nx * nx + ny * ny + footprint * footprint * (1.0 / 12.0);
  // Cut at 3 sigma (the quad's reach), the rest of the Gaussian's weight given back: far tails
  // would reach denormals, which a CPU rasteriser's threads round differently.
  if (!(b2 <= 9.0 * variance)) discard;
  float kernel = (kInvSqrtTwoPi / kWithinThreeSigma) * inversesqrt(variance) *
                 exp(-0.5 * b2 / variance);
#endif
  float level = cameraRelativeLevel();
  float depthBelow = level - onRay.y;
  float rho = godRayParticipation(depthBelow, u.volumeFade.x, u.volumeFade.y);
  if (!(rho > 0.0)) discard;
  float lightPath = beamLightPath + submergedLength(s, beamStart.y - level, onRay.y - level);
  float viewPath = submergedViewLength(t, depthBelow, level);
  vec3 light = beamPower * (kernel * rho * inversesqrt(sin2)) *
               exp(-u.volumeExtinction.rgb * lightPath - u.viewExtinction.rgb * viewPath);
  // Nothing below 1e-30 (denormal products, as above); NaN and Inf never reach the sum.
  if (!(all(lessThan(light, vec3(1e30))) && light.r + light.g + light.b > 1e-30)) discard;
  outLight = vec4(light, 0.0);
}
