// The frame's local water region as the sample's surface draws it (local_water_source.h; the
// plugin's own reading is postfx/local_water.h's, with the same layout): a rectangle with a
// texture of RG = slopes along its local axes, B = height above the level (m).
layout(binding = 6) uniform sampler2D localWaterTexture;
// xy: the region's centre relative to the camera, world xz (m); zw: its local u axis in world
// xz, (cos r, -sin r).
uniform vec4 localWaterFrame;
// xy: 1 / size (1/m); z: 0 no region, 1 Add (on top of the sea), 2 Replace (the sea is not
// read inside); w: 1 when the drawn grid is the region's own square (xy of the vertex in
// [-0.5, 0.5]^2 of the region) rather than the camera-centred sea.
uniform vec4 localWaterExtent;

const float kLocalWaterNone = 0.0, kLocalWaterAdd = 1.0, kLocalWaterReplace = 2.0;

float localWaterMode() {
  return localWaterExtent.z;
}

vec2 localWaterAxisV() {
  return vec2(-localWaterFrame.w, localWaterFrame.z);  // (sin r, cos r)
}

// Camera-relative world xz of a point of the region's square, [-0.5, 0.5]^2 in local u, v.
vec2 localWaterSquareToRelative(vec2 square) {
  vec2 local = square / localWaterExtent.xy;
  return localWaterFrame.xy + local.x * localWaterFrame.zw + local.y * localWaterAxisV();
}

// The region's texture coordinate at a camera-relative world xz, and whether it lies inside.
bool localWaterUv(vec2 relativeXZ, out vec2 uv) {
  vec2 d = relativeXZ - localWaterFrame.xy;
  vec2 local = vec2(dot(d, localWaterFrame.zw), dot(d, localWaterAxisV()));
  uv = local * localWaterExtent.xy + 0.5;
  return localWaterMode() != kLocalWaterNone && all(greaterThanEqual(uv, vec2(0.0))) &&
         all(lessThanEqual(uv, vec2(1.0)));
}

// The height (m) and the world-space slope (dh/dx, dh/dz) at uv.
float localWaterHeight(vec2 uv) {
  return textureLod(localWaterTexture, uv, 0.0).b;
}
vec2 localWaterSlope(vec2 uv) {
  vec2 s = texture(localWaterTexture, uv).rg;
  // The gradient in world xz: dh/du along u plus dh/dv along v.
  return s.x * localWaterFrame.zw + s.y * localWaterAxisV();
}
