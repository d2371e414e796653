// Procedural rock surface for the sample's own rocks and stones: value-noise fBm on world
// position (no UVs needed, no seams), which darkens and lightens the albedo, paints weed on the
// faces that look up, and tilts the normal by the noise's gradient (bumps ~4 cm high).
#ifndef SAMPLE_ROCK_DETAIL_GLSL
#define SAMPLE_ROCK_DETAIL_GLSL

float rockHash(vec3 p) {
  p = fract(p * 0.3183099 + 0.1);
  p *= 17.0;
  return fract(p.x * p.y * p.z * (p.x + p.y + p.z));
}

float rockValueNoise(vec3 x) {
  const vec3 i = floor(x);
  const vec3 f = fract(x);
  const vec3 u = f * f * (3.0 - 2.0 * f);
  return mix(mix(mix(rockHash(i), rockHash(i + vec3(1, 0, 0)), u.x),
                 mix(rockHash(i + vec3(0, 1, 0)), rockHash(i + vec3(1, 1, 0)), u.x), u.y),
             mix(mix(rockHash(i + vec3(0, 0, 1)), rockHash(i + vec3(1, 0, 1)), u.x),
                 mix(rockHash(i + vec3(0, 1, 1)), rockHash(i + vec3(1, 1, 1)), u.x), u.y),
             u.z);
}

// Five octaves from 0.6 m down to 4 cm, each weighted out once its wavelength is under two
// pixel footprints. Range about [0, 1], mean 0.5.
float rockFbm(vec3 p, float footprint) {
  float sum = 0.0, weight = 0.0, amplitude = 0.5, frequency = 1.6;
  for (int octave = 0; octave < 5; ++octave) {
    const float resolved = 1.0 - smoothstep(0.25, 0.5, footprint * frequency);
    sum += amplitude * resolved * rockValueNoise(p * frequency + float(octave) * 7.31);
    weight += amplitude * resolved;
    amplitude *= 0.5;
    frequency *= 2.07;
  }
  return weight > 0.0 ? mix(0.5, sum / weight, min(weight / 0.5, 1.0)) : 0.5;
}

void rockDetail(vec3 world, float footprint, inout vec3 n, inout vec3 colour) {
  const float h = rockFbm(world, footprint);
  // Bumps: the gradient of a 4 cm height field, its part along the surface tilts the normal.
  const float e = 0.03;
  const vec3 gradient = vec3(rockFbm(world + vec3(e, 0, 0), footprint) - h,
                             rockFbm(world + vec3(0, e, 0), footprint) - h,
                             rockFbm(world + vec3(0, 0, e), footprint) - h) *
                        (0.04 / e);
  n = normalize(n - (gradient - dot(gradient, n) * n));
  // Light and dark mineral, then weed where the face looks up and the noise allows.
  colour *= mix(0.4, 1.5, smoothstep(0.3, 0.7, h));
  const float weed = smoothstep(0.35, 0.8, n.y) *
                     smoothstep(0.45, 0.65, rockFbm(world * 0.37 + 3.1, footprint * 0.37));
  colour = mix(colour, vec3(0.16, 0.2, 0.07), 0.6 * weed);
}

#endif
