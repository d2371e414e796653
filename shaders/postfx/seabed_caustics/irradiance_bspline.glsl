// A depth-layered irradiance texture's level 0 reconstructed with the cubic B-spline from four
// bilinear fetches (each pair of B-spline taps per axis is one bilinear fetch between them at the
// ratio of their weights). Bilinear magnification shows the texel grid as creases (its slope
// jumps at every texel edge); the B-spline is C2 across them. Its weights are all positive: no
// negative lobes, so irradiance stays >= 0, flat light stays exactly flat and the mean is kept.
// The taps are computed here and fetched by the caller, so that no sampler is passed to a
// function (some compilers mishandle an element of a sampler array passed on; llvmpipe read
// wrong light).
struct BSplineTaps {
  vec2 c0, c1;  // texture coordinates of the two fetches per axis
  vec2 g0, g1;  // their weights per axis
};

// `texels`: the texture's side.
BSplineTaps bsplineTaps(vec2 uv, float texels) {
  vec2 x = uv * texels - 0.5;
  vec2 i = floor(x);
  vec2 f = x - i;
  vec2 f2 = f * f, f3 = f2 * f;
  vec2 w0 = (1.0 - 3.0 * f + 3.0 * f2 - f3) * (1.0 / 6.0);
  vec2 w1 = (4.0 - 6.0 * f2 + 3.0 * f3) * (1.0 / 6.0);
  vec2 w3 = f3 * (1.0 / 6.0);
  vec2 w2 = 1.0 - w0 - w1 - w3;
  BSplineTaps t;
  t.g0 = w0 + w1;
  t.g1 = w2 + w3;
  // Texel-centre coordinates of the two fetches per axis, back to [0, 1].
  t.c0 = (i - 0.5 + w1 / t.g0) / texels;
  t.c1 = (i + 1.5 + w3 / t.g1) / texels;
  return t;
}

// The four fetches e00, e10, e01, e11 (at (c0.x, c0.y), (c1.x, c0.y), (c0.x, c1.y), (c1.x, c1.y))
// weighed.
float bsplineSum(BSplineTaps t, float e00, float e10, float e01, float e11) {
  return t.g0.y * (t.g0.x * e00 + t.g1.x * e10) + t.g1.y * (t.g0.x * e01 + t.g1.x * e11);
}
