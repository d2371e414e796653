#pragma once
// The object caustics' work in one frame, counted on the CPU before anything is drawn (issue
// 28): the caster triangles drawn into the caster maps and the splats drawn into the caustic
// map, held to CreateDesc::casterTriangleBudget and ::splatBudget. A caster set of 64 meshes
// of 2^31 indices, or the largest grid from every light with dispersion, is refused with a
// message naming the budget instead of being discovered as a GPU stall.
#include <cstdint>
#include <string>

#include <postfx/postfx.h>

#include "core/frame_plan.h"

namespace postfx::detail {

struct ObjectCausticsWork {
  std::int64_t triangles = 0;  // triangles drawn into the caster maps (both faces, every view)
  std::int64_t splats = 0;     // splats drawn into the caustic maps (every view)
  int views = 0;               // the sun's (when it runs) and each local light's that runs
};

// What `plan`'s object-caustics views draw. Counts saturate at INT64_MAX.
ObjectCausticsWork objectCausticsWork(const CreateDesc& create, const FrameDesc& frame,
                                      const FramePlan& plan);

// InvalidArgument naming the budget, the count and where it comes from when the frame's work
// exceeds CreateDesc::casterTriangleBudget or ::splatBudget; Ok otherwise.
Result checkObjectCausticsWork(const CreateDesc& create, const FrameDesc& frame,
                               const FramePlan& plan, std::string& error);

}  // namespace postfx::detail
