// God-ray march math of [1] section 4 (grid of planes, eq. 2), shared by C++ and GLSL:
// the shader runs these bodies and the unit tests evaluate the very same ones on the CPU.
// The grid's up axis follows the refracted sun; only its x' and z' plane families are used
// (x' = k * s and z' = k * s), so in the grid frame a view ray is a 2D DDA over a square lattice.
#ifndef POSTFX_SHARED_GODRAYS_H
#define POSTFX_SHARED_GODRAYS_H
#include "shared/common.h"

SHARED_BEGIN

// "Never": the crossing distance of a family the ray runs parallel to. Finite, so that min()
// and comparisons stay well defined in GLSL (which has no portable infinity literal).
SHARED_CONST float GODRAYS_NEVER = 3.0e38f;
// Below this |direction component| a ray counts as parallel to the family's planes; 1/1e-7 of a
// metre-scale spacing would overflow nothing but would put the next crossing far beyond any
// march, which is what "parallel" means here.
SHARED_CONST float GODRAYS_PARALLEL = 1e-7f;

// Ray parameter between two crossings of one plane family (planes `spacing` apart), or NEVER.
SHARED_FN float godRayCrossingStep(float direction, float spacing) {
  float a = abs(direction);
  return a > GODRAYS_PARALLEL ? spacing / a : GODRAYS_NEVER;
}

// Ray parameter of the first plane crossing strictly after t = `tStart`, for a ray whose grid
// coordinate is `offset` + direction * t and planes at multiples of `spacing`. `offset` is the
// camera's coordinate reduced modulo the spacing (in double on the CPU). A ray starting exactly
// on a plane goes to the NEXT plane: never a zero-length first step. NaN input gives NEVER.
SHARED_FN float godRayFirstCrossing(float offset, float direction, float spacing, float tStart) {
  float step = godRayCrossingStep(direction, spacing);
  if (!(step < GODRAYS_NEVER)) return GODRAYS_NEVER;
  float x = offset + direction * tStart;  // coordinate where the march starts
  float cell = floor(x / spacing);
  float plane = direction > 0.0f ? (cell + 1.0f) * spacing : cell * spacing;
  float t = tStart + (plane - x) / direction;
  // On a plane (or rounded onto it): the next one is a whole step ahead.
  if (!(t > tStart)) t += step;
  return t;
}

// rho of eq. (2): smooth fade-in over `surfaceFade` metres below the level (hides the grid where
// the rays have not focused), times exp(-depth / depthFade) (the paper's out-scattering fade).
// 0 above the water or for NaN.
SHARED_FN float godRayParticipation(float depthBelow, float surfaceFade, float depthFade) {
  if (!(depthBelow > 0.0f)) return 0.0f;
  float rho = 1.0f;
  if (surfaceFade > 0.0f) {
    float t = clamp(depthBelow / surfaceFade, 0.0f, 1.0f);
    rho = t * t * (3.0f - 2.0f * t);
  }
  if (depthFade > 0.0f) rho *= exp(-depthBelow / depthFade);
  return rho;
}

// The in-scattering of a homogeneous segment of length `distance` per unit source:
// integral_0^D sigma_s * exp(-sigma_t * t) dt = sigma_s / sigma_t * (1 - exp(-sigma_t * D)),
// with its limit sigma_s * D as sigma_t -> 0 (no 0/0). Bounded by sigma_s / sigma_t <= 1.
SHARED_FN vec3 godRayInscatter(vec3 sigmaS, vec3 sigmaT, float pathLength) {
  vec3 d = vec3(max(pathLength, 0.0f));
  vec3 big = sigmaS / max(sigmaT, vec3(1e-30f)) * (vec3(1.0f) - exp(-sigmaT * d));
  vec3 small = sigmaS * d;
  return vec3(sigmaT.x * d.x > 1e-4f ? big.x : small.x, sigmaT.y * d.y > 1e-4f ? big.y : small.y,
              sigmaT.z * d.z > 1e-4f ? big.z : small.z);
}

// Parameter range [tStart, tEnd] of a ray (camera-relative, unit `direction`) that lies under
// the water level `levelRelative` (= level - camera y), up to `tMax`. tEnd <= tStart: no water.
SHARED_FN vec2 godRayUnderwaterRange(float levelRelative, float directionY, float tMax) {
  float tStart = 0.0f, tEnd = tMax;
  float tSurface = abs(directionY) > 1e-12f ? levelRelative / directionY : GODRAYS_NEVER;
  if (levelRelative < 0.0f) {  // camera above the water: only a downward ray enters it
    if (!(directionY < 0.0f)) return vec2(0.0f);
    tStart = tSurface;
  } else if (directionY > 0.0f) {  // camera under the water looking up: it ends at the surface
    tEnd = min(tEnd, tSurface);
  }
  return vec2(tStart, tEnd);
}

SHARED_END

#endif
