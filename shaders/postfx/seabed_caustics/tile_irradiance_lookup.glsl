// The tile-irradiance model's lookup, shared by the caustics and the god rays: each cascade's
// periodic irradiance at the receiver's depth, combined coarsest first. Include after
// caustics_io.glsl, water_sampling.glsl and postfx/seabed_caustics/postfx_tile_irradiance.h.
#ifdef POSTFX_TILE_IRRADIANCE
layout(binding = POSTFX_UNIT_TILE_IRRADIANCE) uniform sampler2DArray tileIrradiance;

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
      // Seen through the coarser cascades, which act as a lens of focal power 1 / f, the finer
      // pattern is the one it makes alone at the lens-shortened depth 1 / (1 / d + 1 / f): the
      // coarser focusing E (to first order the inverse of the lens's magnification squared)
      // gives it as d sqrt(E). Where the coarse waves converge light, the fine pattern below is
      // further developed (past its own focus, more scrambled); where they spread it, less.
      float lensDepth = depthBelow * sqrt(clamp(e, 0.1, 10.0));
      float lensLayer = tileLayerCoord(lensDepth, int(u.tileIrradiance.x), u.tileIrradiance.y);
      e *= tileCascadeIrradiance(c, coord, lensLayer, logFootprint);
    }
  }
#endif
  // Clamped as each field is: cascades focusing on one receiver would otherwise multiply their
  // clamps past a half float's range, the packed half-resolution lookups' and RGBA16F targets'.
  return min(e, TILE_MAX_IRRADIANCE);
}

#if POSTFX_WAVEFRONT_AREA_RATIO
// The WavefrontAreaRatio window's irradiance, continued beyond its edge by the tile irradiance:
// the same physics (irradiance of the refracted sun, in the same units) without a window, so
// the fade band blends two estimates of one light rather than two looks. Outside the window
// only the tile is read, inside only the window (a dynamic branch: GPUs skip the other's
// fetches). The seabed caustics and the god rays both light from it.
float windowOrTileIrradiance(vec3 p, float depthBelow, float logFootprint) {
  float physicalWeight = 0.0;
  float windowLight = physicalIrradiance(p, depthBelow, logFootprint, physicalWeight);
  float farLight = physicalWeight < 1.0 ? tileIrradianceAt(p, depthBelow, logFootprint) : 1.0;
  return mix(farLight, windowLight, physicalWeight);
}
#endif
#endif
