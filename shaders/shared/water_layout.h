// The water module's GPU contract, shared by C++ (water/src/shader_interface.h) and GLSL:
// binding points, scratch layout and the phase encoding. One definition, two compilers.
#ifndef POSTFX_SHARED_WATER_LAYOUT_H
#define POSTFX_SHARED_WATER_LAYOUT_H
#include "shared/common.h"

SHARED_BEGIN

SHARED_CONST int WATER_MAX_CASCADES = 4;

// The eight real fields of a cascade travel through the FFT as four complex signals (two real
// fields per complex signal), i.e. two RGBA32F texels per mode: layers 2c and 2c + 1 of the
// scratch array. Layer 2c = (h + i dh/dx, dh/dz + i Dx), layer 2c + 1 = (Dz + i dDx/dx,
// dDz/dz + i dDx/dz).
SHARED_CONST int WATER_SCRATCH_LAYERS_PER_CASCADE = 2;

SHARED_CONST int WATER_SPECTRUM_BINDING = 0;   // shader storage: amplitudes and cycle counts
SHARED_CONST int WATER_SCRATCH_UNIT = 0;       // image unit: RGBA32F scratch array
SHARED_CONST int WATER_SLOPE_UNIT = 1;         // image unit: RGBA16F slope array, level 0
SHARED_CONST int WATER_DISPLACEMENT_UNIT = 2;  // image unit: RGBA16F displacement array, level 0
SHARED_CONST int WATER_IMAGE_UNIT_COUNT = 3;

// A wave's phase is (cycles * loopPhase) mod 2^32 in units of 2 pi / 2^32 (exact in uint math).
SHARED_CONST float WATER_PHASE_TO_RADIANS = 1.4629180792671596e-9f;

// Determinant of the horizontal map x -> x + D(x): 1 flat, < 0 where the surface folds over.
SHARED_FN float waterJacobian(float dDxdx, float dDzdz, float dDxdz) {
  return (1.0f + dDxdx) * (1.0f + dDzdz) - dDxdz * dDxdz;
}

SHARED_END

#endif
