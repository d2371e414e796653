#pragma once
// GPU memory a frame makes the context allocate (its textures and buffers sized by the frame:
// raw output, god-ray march texture, irradiance layers, caster and caustic maps), estimated on
// the CPU before any GL work, so that a setting the budget cannot hold is refused up front
// instead of running out of memory after some light was already added. The small objects
// create() makes (programs, samplers, uniform blocks) are not counted.
#include <cstdint>
#include <span>
#include <string>

#include <postfx/postfx.h>

#include "core/frame_plan.h"

namespace postfx::detail {

// One view of the frame: its frame (its camera and G-buffer), its target's and its viewport's
// size, its plan.
struct ViewMemory {
  const FrameDesc* frame = nullptr;
  int targetWidth = 0, targetHeight = 0;  // the raw output's size
  int width = 0, height = 0;              // the viewport's: the reduced textures'
  const FramePlan* plan = nullptr;
};

// A frame of one view whose viewport is its whole target.
std::uint64_t frameMemoryBytes(const CreateDesc& create, const FrameDesc& frame, int width,
                               int height, const FramePlan& passes);
// Every view's own textures, and the work they share once (the first view's frame and plan
// describe it: the same settings for all).
std::uint64_t frameMemoryBytes(const CreateDesc& create, std::span<const ViewMemory> views);

// OutOfMemory with a message naming the largest consumer when the frame needs more than
// CreateDesc::memoryBudgetMiB; Ok otherwise.
Result checkFrameMemory(const CreateDesc& create, std::span<const ViewMemory> views,
                        std::string& error);

}  // namespace postfx::detail
