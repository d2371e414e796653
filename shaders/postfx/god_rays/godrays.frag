#version 450 core
// Underwater god rays ([1], section 4, eq. 2): march each view ray through a grid of planes
// whose up axis follows the refracted sun and that is snapped to the world, evaluate the caustic
// factor omega where the ray crosses a plane, and average rho_i * omega_i along the ray.
//
// Light model (single scattering of the sun in a homogeneous medium, sigma_t = sigma_a +
// sigma_s, the extinction the host's underwater fog uses):
//   L = E_sun * intensity * integral_0^D sigma_s * S(t) * exp(-sigma_t * t) dt
//   S(t) = rho * omega * shadow * exp(-sigma_t * depth / cos(theta_t))   (sun path in water)
// The integral is the analytic in-scatter of a homogeneous segment (godRayInscatter) times the
// transmittance-weighted mean of S over the samples: gamma = sum(w_i S_i) / sum(w_i),
// w_i = dt_i * exp(-sigma_t * t_i). With w_i = 1 that is the paper's sum(rho_i omega_i) / D_n; the
// weights make it an unbiased quadrature and extend the sampled part's mean over the rest of the
// ray when sampleCount runs out before its end. L <= E * intensity * sigma_s / sigma_t: bounded.
// Light field (omega in S): the seabed caustics' own where the frame's model has one, so that
// the shafts line up with the pattern on the seabed below them: the TileIrradiance variant
// (POSTFX_TILE_IRRADIANCE, built like caustics.frag's) reads the tile irradiance at the sample's
// depth; the WavefrontAreaRatio model (POSTFX_TILE_IRRADIANCE with POSTFX_WAVEFRONT_AREA_RATIO) its depth
// layers inside the window, blended to the tile irradiance beyond it exactly as the seabed is.
// RayDeviation (no POSTFX_TILE_IRRADIANCE) keeps [1]'s factor from the water slopes at each
// sample.
// Compile-time switches: those of caustics.frag, plus POSTFX_GODRAYS_REDUCED (write the reduced-
// size texture: always written, alpha = the pixel's distance for the depth-aware upsample).
#if POSTFX_GODRAYS_REDUCED
#define POSTFX_LOOKUP_TARGET 1  // writes outReduced, not the host's target
#endif
#include "postfx/god_rays/godrays_common.glsl"
#include "postfx/seabed_caustics/postfx_caustics.h"
#include "postfx/god_rays/postfx_godrays.h"
#include "postfx/seabed_caustics/water_sampling.glsl"
// Unconditional: the shader library expands each file once, where it is first named, even
// inside a disabled #if.
#include "postfx/seabed_caustics/postfx_wavefront_area_ratio.h"
#include "postfx/seabed_caustics/postfx_tile_irradiance.h"
#include "postfx/seabed_caustics/postfx_local_water.h"
#include "postfx/seabed_caustics/irradiance_bspline.glsl"
#include "postfx/seabed_caustics/wavefront_area_ratio_lookup.glsl"
#include "postfx/seabed_caustics/local_water_lookup.glsl"
#include "postfx/seabed_caustics/tile_irradiance_lookup.glsl"

// 4x4 ordered dither, fixed on screen and in time: no temporal noise.
float bayer4(ivec2 p) {
  const float m[16] = float[](0.0, 8.0, 2.0, 10.0, 12.0, 4.0, 14.0, 6.0, 3.0, 11.0, 1.0, 9.0,
                              15.0, 7.0, 13.0, 5.0);
  return (m[(p.y & 3) * 4 + (p.x & 3)] + 0.5) * (1.0 / 16.0);
}

// S(t) of the model above at camera-relative point p, t metres along the ray.
vec3 sunSource(vec3 p, float t) {
  float depthBelow = u.depthAndWater.z - p.y;
  float rho = godRayParticipation(depthBelow, g.fade.x, g.fade.y);
  if (!(rho > 0.0)) return vec3(0.0);
#if POSTFX_SHADOW_MASK
  rho *= sunVisibility(p, vec3(0.0));  // no surface: no normal offset
  if (!(rho > 0.0)) return vec3(0.0);
#endif
  // The full-resolution pixel's footprint even when a reduced texel stands for k x k pixels: a
  // coarser mip flattens the slopes before the nonlinear omega and brightens the mean (+10 % at
  // half resolution in the reference test); the upsample is what averages the texels.
  float logFootprint = log2(max(t * u.depthAndWater.w, 1e-6)) + u.oblique.z;
#if defined(POSTFX_TILE_IRRADIANCE) && !POSTFX_WAVEFRONT_AREA_RATIO
  float omega = tileIrradianceAt(p, depthBelow, logFootprint);
#elif defined(POSTFX_TILE_IRRADIANCE)
  float omega = windowOrTileIrradiance(p, depthBelow, logFootprint);  // as the seabed is lit
#else
  float physicalWeight = 0.0;
#if POSTFX_WAVEFRONT_AREA_RATIO
  float physical = physicalIrradiance(p, depthBelow, logFootprint, physicalWeight);
#endif
  // Inside the physical window the slopes are not needed: no cascade is read (on GPUs).
  vec4 cascades = physicalWeight < 1.0 ? selectCascades(depthBelow, logFootprint) : kNoCascades;
  // Looked up where this point's light entered the water, as the caustics pass does.
  vec3 waterNormal =
      waterNormalFromSlopes(cascadeSlopes(lightEntryCoord(p), 1, logFootprint, cascades));
  float omega = causticFactorAcrossIncidence(u.towardSun.xyz, waterNormal, u.eta.g,
                                             u.reference.xyz, u.towardSun.w, u.reference.w);
#if POSTFX_WAVEFRONT_AREA_RATIO
  omega = mix(omega, physical, physicalWeight);
#endif
#endif
#if POSTFX_LOCAL_WATER
  omega = localWaterIrradiance(p, depthBelow, logFootprint, vec3(omega)).r;  // as the seabed
#endif
  return vec3(rho * omega) * exp(-g.sunPath.rgb * depthBelow);
}

#if POSTFX_GODRAYS_REDUCED
// Light and distance as four halves in two words: the upsample gathers each word of a pixel's
// four texels with one fetch (a CPU rasteriser pays per fetch).
layout(location = 0) out uvec2 outReduced;
#endif

void emit(vec3 light, float pixelDistance) {
#if POSTFX_GODRAYS_REDUCED
  outReduced = uvec2(packHalf2x16(light.rg), packHalf2x16(vec2(light.b, pixelDistance)));
#else
  if (!(light.r + light.g + light.b > 0.0)) discard;  // saves the blend; drops NaN too
  outLight = vec4(light, 0.0);
#endif
}

void main() {
#if POSTFX_GODRAYS_REDUCED
  // Reduced texel i stands for full-resolution pixel k*i (the upsample relies on it).
  ivec2 pixel = min(ivec2(gl_FragCoord.xy) * int(g.reduction.x), ivec2(u.viewport.zw) - 1) +
                ivec2(u.viewOrigin.xy);
#else
  ivec2 pixel = ivec2(gl_FragCoord.xy);
#endif
  float pixelDistance;
  vec3 d = mat3(u.viewToWorld) * pixelViewRay(pixel, pixelDistance);
  // Guards: NaN depth, and the underwater part of the ray (zero-length or none: no light).
  if (!(pixelDistance > 0.0) || !(abs(d.y) <= 1.0)) {
    emit(vec3(0.0), kSkyDistance);
    return;
  }
  vec2 range = godRayUnderwaterRange(u.depthAndWater.z, d.y, min(pixelDistance, g.fade.z));
  float tStart = range.x, tEnd = range.y;
  if (!(tEnd > tStart)) {
    emit(vec3(0.0), pixelDistance);
    return;
  }
  int count = int(g.gridZ.w);
  float phase = g.gridOffset.w > 0.5 ? bayer4(ivec2(gl_FragCoord.xy)) : 0.5;
  float uniformPhase = g.gridOffset.w > 0.5 ? phase : g.fade.w;
  vec3 weighted = vec3(0.0), weights = vec3(0.0);
  int taken = 0;
  if (g.gridOffset.z > 0.5) {
    // Uniform along the ray (comparison mode): the samples slide with the camera.
    float dt = (tEnd - tStart) / float(count);
    for (int i = 0; i < GODRAYS_MAX_SAMPLES; ++i) {
      if (i >= count) break;
      float t = tStart + (float(i) + uniformPhase) * dt;
      vec3 w = dt * exp(-g.extinction.rgb * (t - tStart));
      weighted += w * sunSource(d * t, t);
      weights += w;
    }
    taken = count;
  } else {
    // World grid: 2D DDA over the x' and z' plane families. A family the ray is parallel to
    // never fires (its crossing stays at GODRAYS_NEVER).
    float s = g.gridX.w;
    float dx = dot(d, g.gridX.xyz), dz = dot(d, g.gridZ.xyz);
    float shift = g.gridOffset.w > 0.5 ? (phase - 0.5) * s : 0.0;
    float tx = godRayFirstCrossing(g.gridOffset.x + shift, dx, s, tStart);
    float tz = godRayFirstCrossing(g.gridOffset.y + shift, dz, s, tStart);
    float stepX = godRayCrossingStep(dx, s), stepZ = godRayCrossingStep(dz, s);
    float tPrev = tStart;
    for (int i = 0; i < GODRAYS_MAX_SAMPLES; ++i) {
      if (i >= count) break;
      float t = min(tx, tz);
      if (!(t <= tEnd)) break;
      vec3 w = (t - tPrev) * exp(-g.extinction.rgb * (t - tStart));
      weighted += w * sunSource(d * t, t);
      weights += w;
      ++taken;
      tPrev = t;
      // Both families at once where the ray crosses a grid line: no zero-length sample.
      if (tx <= t) tx += stepX;
      if (tz <= t) tz += stepZ;
    }
  }
  if (taken == 0) {
    // A march shorter than one cell crosses no plane: its end point (a world-fixed point of the
    // scene or the surface) stands for it.
    weighted = sunSource(d * tEnd, tEnd);
    weights = vec3(1.0);
  }
  vec3 gamma = vec3(weights.r > 0.0 ? weighted.r / weights.r : 0.0,
                    weights.g > 0.0 ? weighted.g / weights.g : 0.0,
                    weights.b > 0.0 ? weighted.b / weights.b : 0.0);
  vec3 unitLight = godRayInscatter(g.scattering.rgb, g.extinction.rgb, tEnd - tStart) * gamma;
  vec3 light = g.lightScale.rgb * unitLight;
  bool finite = all(lessThan(abs(light), vec3(1e30)));
#if POSTFX_GODRAYS_REDUCED
  // Per unit of the sun's light (at most the field's clamp, whatever the host's units, which
  // halves hold without overflow); the upsample scales it.
  emit(finite ? unitLight : vec3(0.0), pixelDistance);
#else
  emit(finite ? light : vec3(0.0), pixelDistance);
#endif
}
