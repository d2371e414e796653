// The tile irradiance's unresolved-slope spread: the slope statistics' partial sums
// (tile_irradiance_spread.comp writes them) and the landing covariance they give (the blur
// reads it, with TILE_SPREAD_READER defined: the statistics' buffer and the uniforms the
// covariance takes are then declared here, at locations 10 to 14). Include after
// postfx/seabed_caustics/postfx_tile_irradiance.h.

struct TileSpreadPartial {
  vec4 cellMoments;  // xyz: second moments (xx, xz, zz) about each cell's mean, summed; w: cells
};

#ifdef TILE_SPREAD_READER
layout(std430, binding = POSTFX_STORAGE_TILE_SPREAD) readonly buffer TileSpread {
  TileSpreadPartial partials[];  // cascade * TILE_SPREAD_PARTS + part
};

layout(location = 10) uniform ivec4 slotCascade;    // each slot's cascade
layout(location = 11) uniform vec4 texelsPerMetre;  // each slot's irradiance texels per metre
layout(location = 12) uniform vec4 drift;           // tileLinearOffset's J
// xyz: the sun disc's landing covariance (m^2 per metre^2 of depth); w: 1 with the unresolved
// slopes' spread, 0 for the disc alone
layout(location = 13) uniform vec4 sunDisc;
layout(location = 14) uniform int cascades;

// Cascade c's slope covariance (xx, xz, zz) inside a point's cell: the slopes its points do not
// resolve.
vec3 tileCellSlopes(int c) {
  vec4 moments = vec4(0.0);
  for (int p = 0; p < TILE_SPREAD_PARTS; ++p) moments += partials[c * TILE_SPREAD_PARTS + p].cellMoments;
  return moments.xyz / max(moments.w, 1.0);
}

// The part of tileSlotCovariance the slopes inside the cells give (0 with the disc alone): of
// the slot's own cascade and of every finer one (each finer cascade's resolved slopes make its
// own pattern, which multiplies this one; what none resolves scatters them all).
vec3 tileSlotUnresolvedCovariance(int slot) {
  int cascade = slotCascade[slot];
  vec3 slopes = vec3(0.0);
  for (int f = 0; f < POSTFX_MAX_CASCADES; ++f)
    if (f >= cascade && f < cascades) slopes += tileCellSlopes(f);
  return sunDisc.w * tileSpreadCovariance(slopes, drift, texelsPerMetre[slot]);
}

// The sun disc's part of tileSlotCovariance.
vec3 tileSlotDiscCovariance(int slot) {
  float perMetre = texelsPerMetre[slot];
  return sunDisc.xyz * (perMetre * perMetre);
}

// Where a slot's light lands about where its points put it: covariance in texels^2 per metre^2
// of depth. The slopes inside the cells and the sun's disc.
vec3 tileSlotCovariance(int slot) {
  return tileSlotUnresolvedCovariance(slot) + tileSlotDiscCovariance(slot);
}

// Whether C's axes are turned from the grid's enough to need the diagonal pass: a correlation
// of 0.2 turns a 2:1 ellipse by under 8 degrees, which rows and columns alone then ignore.
bool tileSpreadNeedsDiagonal(vec3 c) {
  return abs(c.y) > 0.2 * sqrt(max(c.x * c.z, 0.0));
}
#endif
