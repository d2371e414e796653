#include "cpu_cost.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace ocean::cost {

std::string CpuClass::describe() const {
  char text[1024];
  std::snprintf(text, sizeof(text),
                "  fragment lane (RGBA16F write)   %8.3f ns\n"
                "  scalar ALU op per lane           %8.4f ns\n"
                "  exp2 or log2, beyond an op       %8.4f ns\n"
                "  division or root, beyond an op   %8.4f ns\n"
                "  texture fetch per lane           %8.3f ns\n"
                "  vertex invocation                %8.3f ns\n"
                "  compute invocation               %8.3f ns\n"
                "  primitive                        %8.3f ns\n"
                "  blended byte                     %8.4f ns\n"
                "  atomic add                       %8.3f ns\n"
                "  buffer byte (compute)            %8.4f ns\n"
                "  cleared byte                     %8.4f ns\n"
                "  draw or dispatch                 %8.1f us\n",
                fragmentLane * 1e9, aluOp * 1e9, transcendental * 1e9, division * 1e9, fetch * 1e9,
                vertex * 1e9, computeInvocation * 1e9, primitive * 1e9, blendedByte * 1e9,
                atomic * 1e9, bufferByte * 1e9, clearedByte * 1e9, call * 1e6);
  return text;
}

StepEstimate predictCpu(const postfx::WorkStep& counted, const postfx::WorkStep& driver,
                        const StepAlu& alu, const CpuClass& cpu) {
  const postfx::WorkCounts& c = counted.work;
  const postfx::WorkCounts& d = driver.work;
  auto per = [](std::uint64_t n, std::uint64_t of) {
    return of > 0 ? double(n) / double(of) : 0.0;
  };
  StepEstimate e;
  // llvmpipe's lanes: its own fragment count; each runs the shader's arithmetic and fetches.
  const double lanes = double(d.fragments);
  const double fragmentFetches = per(c.fragmentFetches, c.fragments);
  const double vertexFetches = per(c.fetches - c.fragmentFetches, c.vertices);
  const double computeFetches = per(c.fetches, c.computeInvocations);
  auto arithmetic = [&cpu](const StageAlu& a) {
    return a.ops * cpu.aluOp + a.transcendental * cpu.transcendental + a.division * cpu.division;
  };
  e.shading = lanes * (cpu.fragmentLane + arithmetic(alu.fragment)) +
              double(c.vertices) * (cpu.vertex + arithmetic(alu.vertex)) +
              double(c.computeInvocations) * (cpu.computeInvocation + arithmetic(alu.compute));
  e.texture = (lanes * fragmentFetches + double(c.vertices) * vertexFetches +
               double(c.computeInvocations) * computeFetches) *
              cpu.fetch;
  // Memory on its own: clears, and what compute steps move in buffers and images (a draw's
  // reads are its fetches, its writes its lanes' and blends').
  const double bytes = double(c.bytesRead + c.bytesWritten);
  e.memory = c.clears > 0       ? bytes * cpu.clearedByte
             : c.dispatches > 0 ? bytes * cpu.bufferByte
                                : 0.0;
  e.raster = double(d.primitives) * cpu.primitive;
  e.rop = double(c.blendedSamples) * double(counted.targetBytes) * cpu.blendedByte;
  e.atomics = double(c.atomics) * cpu.atomic;
  e.overhead = double(c.draws + c.dispatches) * cpu.call;
  e.seconds = e.shading + e.texture + e.memory + e.raster + e.rop + e.atomics + e.overhead;
  const std::pair<double, const char*> terms[] = {
      {e.shading, "shading"}, {e.texture, "texture"}, {e.memory, "memory"},    {e.raster, "raster"},
      {e.rop, "rop"},         {e.atomics, "atomics"}, {e.overhead, "overhead"}};
  e.bound = std::max_element(std::begin(terms), std::end(terms), [](const auto& a, const auto& b) {
              return a.first < b.first;
            })->second;
  return e;
}

}  // namespace ocean::cost
