// The G-buffer contract, shared by C++ (gbuffer/include/gbuffer/codec.h) and GLSL:
// normal encodings and depth-to-position reconstruction. One body, two compilers, so the
// CPU mirror the tests use can never drift from what the shaders do.
#ifndef POSTFX_SHARED_GBUFFER_CODEC_H
#define POSTFX_SHARED_GBUFFER_CODEC_H
#include "shared/common.h"

SHARED_BEGIN

// Depth conventions (values of gbuffer::DepthConvention).
SHARED_CONST int DEPTH_REVERSE_Z = 0;         // clip control [0,1], near = 1, far/sky = 0
SHARED_CONST int DEPTH_FORWARD_ZERO_ONE = 1;  // clip control [0,1], near = 0, far/sky = 1
SHARED_CONST int DEPTH_FORWARD_NEG_ONE = 2;   // GL default [-1,1] clip, window depth near 0, far 1

// Normal encodings (values of gbuffer::NormalEncoding).
SHARED_CONST int NORMAL_OCTAHEDRAL = 0;  // RG16_SNORM or RG16F/RG32F: octahedral in [-1,1]^2
SHARED_CONST int NORMAL_XYZ = 1;         // RGB(A)16F/32F: the world-space vector itself
SHARED_CONST int NORMAL_XYZ_UNORM = 2;   // RGB(A)8 or RGB10_A2 UNORM: n * 0.5 + 0.5

SHARED_FN vec2 signNotZero(vec2 v) {
  return vec2(v.x >= 0.0f ? 1.0f : -1.0f, v.y >= 0.0f ? 1.0f : -1.0f);
}

// Octahedral encoding (Cigolle et al. 2014). Input need not be normalized; zero maps to (0,0).
SHARED_FN vec2 octEncode(vec3 n) {
  float l1 = abs(n.x) + abs(n.y) + abs(n.z);
  if (!(l1 > 0.0f)) return vec2(0.0f);
  vec2 p = vec2(n.x, n.y) / l1;
  if (n.z < 0.0f) p = (vec2(1.0f) - abs(vec2(p.y, p.x))) * signNotZero(p);
  return p;
}

// Returns a unit vector, or zero when the texel held nothing usable (zero or NaN).
SHARED_FN vec3 safeNormalize(vec3 v) {
  float len2 = dot(v, v);
  // !(x > 0) is also true for NaN, which the host's G-buffer may hold.
  if (!(len2 > 1e-20f) || len2 > 1e30f) return vec3(0.0f);
  return v / sqrt(len2);
}

SHARED_FN vec3 octDecode(vec2 e) {
  vec3 n = vec3(e.x, e.y, 1.0f - abs(e.x) - abs(e.y));
  if (n.z < 0.0f) {
    vec2 folded = (vec2(1.0f) - abs(vec2(n.y, n.x))) * signNotZero(vec2(n.x, n.y));
    n.x = folded.x;
    n.y = folded.y;
  }
  return safeNormalize(n);
}

SHARED_FN vec3 decodeNormal(vec4 texel, int encoding) {
  if (encoding == NORMAL_OCTAHEDRAL) return octDecode(vec2(texel.x, texel.y));
  if (encoding == NORMAL_XYZ_UNORM) return safeNormalize(vec3(texel) * 2.0f - vec3(1.0f));
  return safeNormalize(vec3(texel));
}

SHARED_FN vec4 encodeNormal(vec3 n, int encoding) {
  if (encoding == NORMAL_OCTAHEDRAL) return vec4(octEncode(n), 0.0f, 0.0f);
  vec3 unit = safeNormalize(n);
  if (encoding == NORMAL_XYZ_UNORM) return vec4(unit * 0.5f + vec3(0.5f), 1.0f);
  return vec4(unit, 0.0f);
}

// Window depth -> NDC z for the convention.
SHARED_FN float ndcDepth(float depth, int convention) {
  return convention == DEPTH_FORWARD_NEG_ONE ? depth * 2.0f - 1.0f : depth;
}

// True for the sky: nothing was drawn there (the clear value of the convention).
SHARED_FN bool isSkyDepth(float depth, int convention) {
  if (!(depth == depth)) return true;  // NaN in the host's depth: treat as nothing drawn
  return convention == DEPTH_REVERSE_Z ? depth <= 0.0f : depth >= 1.0f;
}

// Perspective projection parameters that reconstruction needs, from a column-major matrix P:
// xyParams = (P[0][0], P[1][1], P[2][0], P[2][1]): focal scales and off-centre (jitter-free)
// terms. zParams = (P[2][2] + k, P[3][2]) with k = 0 for reverse-Z and 1 for the forward
// conventions, computed in double on the CPU (gbuffer::projectionParams).
// Why the k: forward depth crowds toward 1 at distance, and ndcZ + P22 then cancels to a tiny
// number; P22 rounded to float alone costs ~1e-3 relative error at 1.5 km. (ndcZ - 1) is exact
// in float there (Sterbenz) and P22 + 1 = n / (n - f) is small and exact enough, so the sum
// keeps the precision the stored depth has. Reverse-Z needs no such help (P22 = 0).
SHARED_FN float depthDenominator(float ndcZ, float zParamX, int convention) {
  return convention == DEPTH_REVERSE_Z ? ndcZ + zParamX : (ndcZ - 1.0f) + zParamX;
}

// View-space position (camera looks down -Z) from a pixel's uv in [0,1]^2 and its window depth.
// Solving the projection directly (instead of multiplying by an inverse 4x4) keeps the error
// small at far depths, where the inverse's large entries cancel.
SHARED_FN vec3 viewPositionFromDepth(vec2 uv, float depth, vec4 xyParams, vec2 zParams,
                                     int convention) {
  float ndcZ = ndcDepth(depth, convention);
  float viewZ = -zParams.y / depthDenominator(ndcZ, zParams.x, convention);
  vec2 ndcXY = uv * 2.0f - vec2(1.0f);
  float x = -viewZ * (ndcXY.x + xyParams.z) / xyParams.x;
  float y = -viewZ * (ndcXY.y + xyParams.w) / xyParams.y;
  return vec3(x, y, viewZ);
}

SHARED_END

#endif
