#version 450 core
// Seabed caustics (seed 002, section 4) added into the host's HDR target. Compile-time
// switches: POSTFX_DEPTH_CONVENTION, POSTFX_NORMAL_ENCODING, POSTFX_DISPERSION,
// POSTFX_SHADOW_MASK, POSTFX_RAW_OUTPUT, POSTFX_WATER_SINGLE_2D, POSTFX_PHYSICAL,
// POSTFX_TRIPLANAR_WALLS, POSTFX_CASCADE_SLOTS; the TileIrradiance variant defines
// POSTFX_TILE_IRRADIANCE and POSTFX_TILE_GROUPS (RGBA fetches per cascade: 4 depth layers each).
#include "postfx/caustics_io.glsl"
#include "shared/gbuffer_codec.h"
#include "shared/postfx_caustics.h"
#include "postfx/water_sampling.glsl"
// Unconditional: the shader library expands each file once, where it is first named, even
// inside a disabled #if (the tile irradiance header needs it too).
#include "shared/postfx_irradiance.h"
#include "shared/postfx_tile_irradiance.h"
#if POSTFX_PHYSICAL

layout(binding = POSTFX_UNIT_IRRADIANCE) uniform sampler2DArray causticIrradiance;

// Layer k's irradiance at receiver p (camera-relative) `depthBelow` under the level, each
// layer looked up where ITS ray through the same surface point lands: the pattern is moved
// along the flat-water drift by the depth difference, so that the interpolation mixes the
// same caustic features at two stages of focus rather than two unrelated patterns.
// Filtered over the pixel's footprint (lod: log2 of its side in texels): irradiance is linear,
// so a far pixel gets the mean light over what it covers instead of one texel's sparkle.
float layerIrradiance(vec3 p, float depthBelow, float layer, float lod) {
  float layerDepth = packedLayerDepth(u.irradianceDepths[0], u.irradianceDepths[1], int(layer));
  vec2 xz = layerSamplePoint(p.xz, depthBelow, layerDepth, u.oblique.xy);
  vec2 uv = (xz - u.irradianceWindow.xy) * u.irradianceWindow.z;
  return textureLod(causticIrradiance, vec3(uv, layer), lod).r;
}

// Seed-004 irradiance at camera-relative p, depthBelow under the level, interpolated between
// the depth layers around it; `weight` is how much of it to use (0 outside the window).
float physicalIrradiance(vec3 p, float depthBelow, float logFootprint, out float weight) {
  weight = 0.0;
  int layers = int(u.irradianceWindow.w);
  if (layers <= 0) return 1.0;
  // The fade follows the camera continuously (p is camera-relative): the texture's window snaps
  // in steps of the coarsest mip texel, and a fade tied to it would jump with each step. Shrunk
  // by one such step, it stays inside the texture.
  vec2 uv = p.xz * u.irradianceWindow.z + 0.5;
  float texels = float(textureSize(causticIrradiance, 0).x);
  float margin = float(1 << IRRADIANCE_MIP_LEVELS) / texels;
  float edge = min(min(uv.x, uv.y), min(1.0 - uv.x, 1.0 - uv.y)) - margin;
  weight = smoothstep(0.0, IRRADIANCE_FADE_BAND, edge);
  if (!(weight > 0.0)) return 1.0;
  vec3 blend = layerBlend(depthBelow, u.irradianceDepths[0], u.irradianceDepths[1], layers);
  // Texels per metre: the texture's side over the window's.
  float lod = logFootprint + log2(texels * u.irradianceWindow.z);
  float lower = blend.x < 0.0 ? 1.0 : layerIrradiance(p, depthBelow, blend.x, lod);
  float upper = layerIrradiance(p, depthBelow, blend.y, lod);
  return mix(lower, upper, blend.z);
}
#endif

#ifdef POSTFX_TILE_IRRADIANCE
layout(binding = POSTFX_UNIT_IRRADIANCE) uniform sampler2DArray tileIrradiance;

// Cascade c's own irradiance where its light lands at entry coordinate `coord` (m), interpolated
// between the depth layers around the receiver (1 above the first: flat water at the surface).
// Which cascades have irradiance is compiled in (POSTFX_TILE_CASCADES, a bit per cascade): a
// fetch under a run-time condition costs a CPU rasteriser as much as an unconditional one.
float tileCascadeIrradiance(int c, vec2 coord, float layerCoord, float logFootprint) {
  float e = 1.0;
  if (((POSTFX_TILE_CASCADES >> c) & 1) != 0) {  // constant once the loop is unrolled
    // The array layer is compile-time too: the cascade's slot among the masked ones, times the
    // layer groups (TileIrradiancePass's layout), so every index of the fetch folds to a constant.
    float layer = float(bitCount(POSTFX_TILE_CASCADES & ((1 << c) - 1)) * POSTFX_TILE_GROUPS);
    vec3 at = vec3(u.cascadeOblique[c].xy + coord * u.cascadeAxes[c].w, layer);
    float lod = logFootprint + u.cascadeSkip[c].w;
    e = dot(textureLod(tileIrradiance, at, lod), tileLayerWeights(layerCoord, 0)) +
        max(-layerCoord, 0.0);
#if POSTFX_TILE_GROUPS > 1
    e += dot(textureLod(tileIrradiance, at + vec3(0.0, 0.0, 1.0), lod),
             tileLayerWeights(layerCoord, 1));
#endif
  }
  return e;
}

// Cascade c's slopes and height at entry coordinate `coord` (m), at its footprint's mip level
// (aliased slopes would scatter the finer cascades' lookups).
vec3 tileCascadeSurface(int c, vec2 coord, float logFootprint) {
  vec2 uv = u.cascadeOblique[c].xy + coord * u.cascadeAxes[c].w;
  return textureLod(waterSurface, WATER_COORD(uv, c), logFootprint + u.cascadeOblique[c].z).rgb;
}

// The product of the cascades' own irradiances, coarsest first, each looked up where the light
// it focuses came from: the coarser cascades refract that light sideways by an offset that
// varies slowly on the finer cascade's scale, so the finer pattern arrives shifted by it (and
// concentrated by the coarser focus, the product). Scale separation of the cascades is what
// makes this close to tracing through their sum; `ocean_sample compare` and
// postfx_tile_irradiance_tests measure how close (correlation 0.9 with traced light).
float tileIrradianceAt(vec3 p, float depthBelow, float logFootprint) {
  float layerCoord = tileLayerCoord(depthBelow, int(u.tileIrradiance.x), u.tileIrradiance.y);
  vec2 entry = lightEntryCoord(p);
  vec2 flatDrift = -u.oblique.xy;
  int cascades = int(u.oblique.w);
  float e = tileCascadeIrradiance(0, entry, layerCoord, logFootprint);
#if POSTFX_CASCADE_SLOTS > 1
  vec3 coarse = vec3(0.0);
  vec2 coord = entry;
  for (int c = 1; c < POSTFX_CASCADE_SLOTS; ++c) {  // unrolled: constant bound
    // Only where a finer cascade has irradiance to move (constant once unrolled).
    if ((POSTFX_TILE_CASCADES >> c) != 0 && c < cascades) {
      coarse += tileCascadeSurface(c - 1, coord, logFootprint);
      coord = entry - tileLinearOffset(coarse, u.tileDrift, flatDrift, depthBelow);
      e *= tileCascadeIrradiance(c, coord, layerCoord, logFootprint);
    }
  }
#endif
  return e;
}
#endif

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
  vec3 viewPos = viewPositionFromDepth(gl_FragCoord.xy * u.viewport.xy, depth, u.projection,
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
  float facing = max(abs(dot(n, p)) / max(distance, 1e-6), 0.25);
  float logFootprint = log2(max(distance * u.depthAndWater.w / facing, 1e-6)) + u.oblique.z;

#ifdef POSTFX_TILE_IRRADIANCE
  vec3 omega = vec3(tileIrradianceAt(p, depthBelow, logFootprint));
#else
  float tau = u.towardSun.w;
  float reflectionWeight = u.reference.w;
  float physicalWeight = 0.0;
#if POSTFX_PHYSICAL
  // One irradiance for all channels: the mesh is refracted with the mean IOR.
  vec3 physical = vec3(physicalIrradiance(p, depthBelow, logFootprint, physicalWeight));
#endif
  // Inside the physical window the seed-002 lookups are not needed: zero weights skip their
  // fetches (on GPUs; a CPU rasteriser runs them masked).
  vec4 cascades = physicalWeight < 1.0 ? selectCascades(depthBelow, logFootprint) : kNoCascades;
  vec3 waterNormal = waterNormalFromSlopes(waterSlopes(p, n, logFootprint, cascades));
#if POSTFX_DISPERSION
  vec3 omega = causticFactorRgb(u.towardSun.xyz, waterNormal, u.eta.rgb, tau, reflectionWeight);
#else
  vec3 omega = vec3(causticFactor(u.towardSun.xyz, waterNormal, u.eta.g, tau, reflectionWeight));
#endif
#if POSTFX_PHYSICAL
  omega = mix(omega, physical, physicalWeight);
#endif
#endif  // POSTFX_TILE_IRRADIANCE
  vec3 raw = omega * (nDotL * visibility * causticSurfaceFade(depthBelow, u.refractedUp.w));
  vec3 albedo = sanitizeAlbedo(texelFetch(gbufferAlbedo, pixel, 0).rgb);
  vec3 light =
      albedo * u.lightScale.rgb * causticTransmittance(u.absorptionPerDepth.rgb, depthBelow);
  // ViewExtinction::Plugin: from the receiver to the camera, once (the host's fog must not).
  light *=
      exp(-u.viewExtinction.rgb * submergedViewLength(distance, depthBelow, u.depthAndWater.z));
  outLight = vec4(light * raw, 0.0);
#if POSTFX_RAW_OUTPUT
  outRaw = (raw.r + raw.g + raw.b) * (1.0 / 3.0);
#endif
}
