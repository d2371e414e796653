// What a mirror sees far away along a direction, for the glass and metal of the scene: no
// scene geometry, only the sky and the water. Needs sample_frame.h, sample_optics.h and
// water_column.glsl. The sun's disc is left out: sunSpecular() is the sun.

// Radiance arriving along unit `dir` at a point `height` m above the water plane.
vec3 environmentRadiance(vec3 dir, float height) {
  const vec3 noSun = vec3(0.0, -1.0, 0.0);  // skyRadiance's sun terms vanish for dir.y >= 0
  float ior = waterParams.x;
  vec3 sigmaT = absorption.rgb + scattering.rgb;
  vec3 deep = waterInscatter(scattering.rgb, sigmaT, ambient.rgb, max(-height, 0.0));
  if (height >= 0.0) {
    if (dir.y >= 0.0) return skyRadiance(dir, noSun);
    // The sea from above: the sky it reflects and the deep water below its surface.
    float f = fresnelReflectance(-dir.y, 1.0, ior);
    return f * skyRadiance(reflect(dir, vec3(0.0, 1.0, 0.0)), noSun) + (1.0 - f) * deep;
  }
  if (dir.y <= 0.0) return deep;
  // Up to the (mean) surface, through the water in between.
  vec3 surface = belowSurfaceRadiance(dir, vec3(0.0, -1.0, 0.0), noSun, deep);
  vec3 transmittance = exp(-sigmaT * (-height / max(dir.y, 1e-3)));
  return deep + transmittance * (surface - deep);
}

// The sun reflected by a surface of GGX roughness toward the camera (radiance): n unit normal,
// v unit camera -> surface, f0 the reflectance at normal incidence, shadow its lit share.
// Under the water the sun comes along the refracted beam, attenuated by absorption down to the
// point; the waves spread it, so the lobe is never narrower than alpha 0.08 there.
vec3 sunSpecular(vec3 n, vec3 v, vec3 f0, float roughness, float height, float shadow) {
  if (sunDirection.w <= 0.0 || shadow <= 0.0) return vec3(0.0);
  vec3 l = sunDirection.xyz;
  vec3 irradiance = sunIrradiance.rgb;
  if (height < 0.0) {
    l = refractedSun.xyz;
    irradiance *= refractedSun.w * exp(-absorption.rgb * (-height / max(l.y, 1e-3)));
  }
  float nl = dot(n, l), nv = -dot(n, v);
  if (nl <= 0.0 || nv <= 0.0) return vec3(0.0);
  vec3 h = normalize(l - v);
  float alpha = max(roughness * roughness, height < 0.0 ? 0.08 : 0.02);
  float a2 = alpha * alpha;
  float nh = max(dot(n, h), 0.0);
  float d = a2 / (3.14159265 * pow(nh * nh * (a2 - 1.0) + 1.0, 2.0));
  float k = 0.5 * alpha;
  float g = nl / (nl * (1.0 - k) + k) * nv / (nv * (1.0 - k) + k);
  vec3 f = f0 + (1.0 - f0) * pow(1.0 - max(dot(h, l), 0.0), 5.0);
  return d * g * f / (4.0 * nl * nv) * irradiance * nl * shadow;
}
