// Where a camera-relative point lies in the sun's shadow map. The map is drawn along the
// refracted sun (renderer.cpp): exact at and below the level, where the plugin's caustics are
// the sample's sun. With a bend (waterParams.zw: RenderSettings::airShadows) a point above the
// level is moved to the point at its height on the refracted ray from where its sunbeam meets
// the water: every point of one beam, in the air and in the water, then falls on one texel,
// nearer the light the higher it is, and the one map holds the air's shadows and the water's
// (exact for triangles on one side of the level, which the harbour's meshes are). Needs
// shared/sample_frame.h.
vec3 shadowSpace(vec3 relative) {
  float height = cameraHeight.x + relative.y;  // metres above the level
  if ((waterParams.z == 0.0 && waterParams.w == 0.0) || height <= 0.0) return relative;
  return relative + vec3(waterParams.z, 0.0, waterParams.w) * height;
}
