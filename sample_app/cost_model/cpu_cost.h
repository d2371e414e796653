#pragma once
// The same work account turned into time on this machine's CPU rasteriser (Mesa's llvmpipe), to
// check the model where it can be checked (docs/gpu_cost.md, check b): each kind of work at the
// cost a microbenchmark measured for it alone (cpu_calibration.h), summed, not the largest, since
// a CPU core does one thing after another. llvmpipe shades whole 4 x 4 blocks (16 lanes for
// every block a primitive touches: its own fragment count) and samples for every lane.
#include <postfx/diagnostics.h>

#include <string>

#include "gpu_cost.h"

namespace ocean::cost {

// Seconds per unit of each kind of work, as measured here (all threads llvmpipe runs).
struct CpuClass {
  double fragmentLane = 0.0;    // a lane of a fragment shader that writes one RGBA16F sample
  double aluOp = 0.0;           // a scalar arithmetic instruction, per lane
  double transcendental = 0.0;  // an exp2 or log2 (pow, sine, cosine alike), beyond an op
  double division = 0.0;        // a division or square root, beyond an op
  double fetch = 0.0;   // a texture fetch per lane: trilinear, RGBA16F array, a level per pixel
  double vertex = 0.0;  // a vertex shader invocation
  double computeInvocation = 0.0;
  double primitive = 0.0;    // a primitive set up and rasterised
  double blendedByte = 0.0;  // per byte of a blended sample, beyond writing it
  double atomic = 0.0;      // an atomic add, four at a time at neighbouring texels of a 4 MiB field
  double bufferByte = 0.0;  // a byte a compute shader reads or writes in a buffer or image
  double clearedByte = 0.0;      // a byte cleared
  double call = 0.0;             // a draw or dispatch (its scene flush, its bins)
  std::string describe() const;  // the constants, one line each, with units
};

// `counted`: the step counted in its shaders (CountShaderWork); `driver`: the same step's
// driver counts (llvmpipe's lanes).
StepEstimate predictCpu(const postfx::WorkStep& counted, const postfx::WorkStep& driver,
                        const StepAlu& alu, const CpuClass& cpu);

}  // namespace ocean::cost
