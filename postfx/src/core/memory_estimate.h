#pragma once
// GPU memory a frame makes the context allocate (its textures and buffers sized by the frame:
// raw output, god-ray march texture, irradiance layers, caster and caustic maps), estimated on
// the CPU before any GL work, so that a setting the budget cannot hold is refused up front
// instead of running out of memory after some light was already added. The small objects
// create() makes (programs, samplers, uniform blocks) are not counted.
#include <cstdint>
#include <string>

#include <postfx/postfx.h>

#include "core/frame_plan.h"

namespace postfx::detail {

std::uint64_t frameMemoryBytes(const CreateDesc& create, const FrameDesc& frame, int width,
                               int height, const FramePlan& passes);

// OutOfMemory with a message naming the largest consumer when the frame needs more than
// CreateDesc::memoryBudgetMiB; Ok otherwise.
Result checkFrameMemory(const CreateDesc& create, const FrameDesc& frame, int width, int height,
                        const FramePlan& passes, std::string& error);

}  // namespace postfx::detail
