#version 450 core
// Seabed caustics ([1], section 4) added into the host's HDR target. Compile-time
// switches: POSTFX_DEPTH_CONVENTION, POSTFX_NORMAL_ENCODING, POSTFX_DISPERSION,
// POSTFX_SHADOW_MASK, POSTFX_RAW_OUTPUT, POSTFX_WATER_SINGLE_2D, POSTFX_WAVEFRONT_AREA_RATIO,
// POSTFX_TRIPLANAR_WALLS, POSTFX_CASCADE_SLOTS, POSTFX_LOCAL_WATER (the regions' light over the
// model's); the variants that read the tile irradiance
// define POSTFX_TILE_IRRADIANCE and POSTFX_TILE_GROUPS (RGBA fetches per cascade: 4 depth layers
// each): the TileIrradiance model (POSTFX_WAVEFRONT_AREA_RATIO 0; POSTFX_TILE_REDUCED where its lookups ran
// at half resolution, tile_irradiance_reduced.frag) and the WavefrontAreaRatio window continued
// by it (POSTFX_WAVEFRONT_AREA_RATIO 1, looked up per pixel).
#include "postfx/seabed_caustics/caustics_io.glsl"
#include "shared/gbuffer_codec.h"
#include "postfx/seabed_caustics/postfx_caustics.h"
#include "postfx/seabed_caustics/water_sampling.glsl"
// Unconditional: the shader library expands each file once, where it is first named, even
// inside a disabled #if (the tile irradiance header needs it too).
#include "postfx/seabed_caustics/postfx_wavefront_area_ratio.h"
#include "postfx/seabed_caustics/postfx_tile_irradiance.h"
#include "postfx/seabed_caustics/postfx_local_water.h"
#include "postfx/seabed_caustics/irradiance_bspline.glsl"
#include "postfx/seabed_caustics/wavefront_area_ratio_lookup.glsl"
#include "postfx/seabed_caustics/local_water_lookup.glsl"
#include "postfx/seabed_caustics/tile_irradiance_lookup.glsl"
#include "postfx/seabed_caustics/tile_irradiance_upsample.glsl"

#if POSTFX_TRIPLANAR_WALLS
// Tri-planar weights below this skip their projection's fetches (on GPUs).
const float kMinPlaneWeight = 0.02;

// Seed 002's tri-planar lookup: the plane facing up projects the receiver along the refracted
// light onto the water plane (where its light entered); walls use the world (z, y) and (x, y)
// planes. Blended by the G-buffer normal.
vec2 waterSlopes(vec3 p, vec3 n, float logFootprint, vec4 cascades) {
  vec3 w = pow(abs(n), vec3(u.eta.w));
  w /= max(w.x + w.y + w.z, 1e-20);
  vec2 slopes = vec2(0.0);
  if (w.y > kMinPlaneWeight)
    slopes += w.y * cascadeSlopes(lightEntryCoord(p), 1, logFootprint, cascades);
  if (w.x > kMinPlaneWeight) slopes += w.x * cascadeSlopes(p.zy, 0, logFootprint, cascades);
  if (w.z > kMinPlaneWeight) slopes += w.z * cascadeSlopes(p.xy, 2, logFootprint, cascades);
  return slopes;
}
#else
// Every surface, whatever its orientation, is lit by the light that entered the water where the
// refracted sun through it meets the water plane: one projection, continuous across surfaces.
vec2 waterSlopes(vec3 p, vec3 n, float logFootprint, vec4 cascades) {
  return cascadeSlopes(lightEntryCoord(p), 1, logFootprint, cascades);
}
#endif

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  float depth = texelFetch(gbufferDepth, pixel, 0).r;
  if (isSkyDepth(depth, POSTFX_DEPTH_CONVENTION)) {
    emitNothing();
    return;
  }
  vec3 viewPos = viewPositionFromDepth((gl_FragCoord.xy - u.viewOrigin.xy) * u.viewport.xy, depth, u.projection,
                                       u.depthAndWater.xy, POSTFX_DEPTH_CONVENTION);
  vec3 p = mat3(u.viewToWorld) * viewPos;  // camera-relative world position
  float depthBelow = u.depthAndWater.z - p.y;
  if (!(depthBelow > 0.0)) {  // above the water (or NaN from a broken depth texel)
    emitNothing();
    return;
  }
  vec3 n = decodeNormal(texelFetch(gbufferNormal, pixel, 0), POSTFX_NORMAL_ENCODING);
  float nDotL = dot(n, u.refractedUp.xyz);  // 0 for a zero/NaN G-buffer normal
  if (!(nDotL > 0.0)) {
    emitNothing();
    return;
  }
  float visibility = 1.0;
#if POSTFX_SHADOW_MASK
  visibility = sunVisibility(p, n);
  if (!(visibility > 0.0)) {
    emitNothing();
    return;
  }
#endif
  // Pixel footprint in metres, widened where the surface is seen at a grazing angle.
  float distance = length(viewPos);
  float logFootprint = surfaceLogFootprint(n, p, distance);

#if defined(POSTFX_TILE_IRRADIANCE) && !POSTFX_WAVEFRONT_AREA_RATIO
#if POSTFX_TILE_REDUCED
  vec3 omega = vec3(upsampledTileIrradiance(pixel - ivec2(u.viewOrigin.xy), distance));
#else
  vec3 omega = vec3(tileIrradianceAt(p, depthBelow, logFootprint));
#endif
#elif defined(POSTFX_TILE_IRRADIANCE)
  vec3 omega = vec3(windowOrTileIrradiance(p, depthBelow, logFootprint));
#else
  float tau = u.towardSun.w;
  float reflectionWeight = u.reference.w;
  float physicalWeight = 0.0;
#if POSTFX_WAVEFRONT_AREA_RATIO
  // One irradiance for all channels: the mesh is refracted with the mean IOR.
  vec3 physical = vec3(physicalIrradiance(p, depthBelow, logFootprint, physicalWeight));
#endif
  // Inside the window the ray-deviation lookups are not needed: zero weights skip their
  // fetches (on GPUs; a CPU rasteriser runs them masked).
  vec4 cascades = physicalWeight < 1.0 ? selectCascades(depthBelow, logFootprint) : kNoCascades;
  vec3 waterNormal = waterNormalFromSlopes(waterSlopes(p, n, logFootprint, cascades));
#if POSTFX_DISPERSION
  vec3 omega = causticFactorRgb(u.towardSun.xyz, waterNormal, u.eta.rgb, tau, reflectionWeight);
#else
  vec3 omega = vec3(causticFactor(u.towardSun.xyz, waterNormal, u.eta.g, tau, reflectionWeight));
#endif
#if POSTFX_WAVEFRONT_AREA_RATIO
  omega = mix(omega, physical, physicalWeight);
#endif
#endif  // the model
#if POSTFX_LOCAL_WATER
  omega = localWaterIrradiance(p, depthBelow, logFootprint, omega);
#endif
  vec3 raw = omega * (nDotL * visibility * causticSurfaceFade(depthBelow, u.refractedUp.w));
  vec3 albedo = sanitizeAlbedo(texelFetch(gbufferAlbedo, pixel, 0).rgb);
  // Beer-Lambert along the refracted sun path to the receiver (causticTransmittance) and, with
  // ViewExtinction::Plugin, from the receiver to the camera, once (the host's fog must not):
  // one exp for both.
  float viewLength = submergedViewLength(distance, depthBelow, u.depthAndWater.z);
  vec3 light = albedo * u.lightScale.rgb *
               exp(-(u.absorptionPerDepth.rgb * depthBelow + u.viewExtinction.rgb * viewLength));
  outLight = vec4(light * raw, 0.0);
#if POSTFX_RAW_OUTPUT
  outRaw = (raw.r + raw.g + raw.b) * (1.0 / 3.0);
#endif
}
