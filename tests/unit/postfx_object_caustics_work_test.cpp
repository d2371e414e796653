// The object caustics' work budget (CreateDesc::casterTriangleBudget and
// ::splatBudget), counted on the CPU: what a caster set asks of the GPU in one frame, exactly
// and without overflow for any counts a host passes.
#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "object_caustics/object_caustics_work.h"

namespace {

using postfx::detail::FramePlan;
using postfx::detail::objectCausticsWork;

postfx::CasterMesh caster(std::int64_t indexCount) {
  postfx::CasterMesh m;
  m.vertexBuffer = 1;  // never read: the count is the host's word
  m.indexBuffer = 1;
  m.vertexCount = 3;
  m.indexCount = indexCount;
  return m;
}

FramePlan sunOnly() {
  FramePlan plan;
  plan.objects = true;
  return plan;
}

TEST(PostfxObjectCausticsWork, CountsEachCastersFacesAndTheGridsSplats) {
  const std::vector<postfx::CasterMesh> casters = {caster(3000), caster(300)};
  postfx::FrameDesc frame;
  frame.objectCaustics.casters = casters.data();
  frame.objectCaustics.casterCount = 2;
  frame.objectCaustics.settings.gridSize = 256;
  postfx::CreateDesc create;
  create.features = postfx::Feature::ObjectCaustics;
  const auto work = objectCausticsWork(create, frame, sunOnly());
  EXPECT_EQ(work.triangles, 2 * (1000 + 100));  // front and back faces
  EXPECT_EQ(work.splats, 256 * 256);
  EXPECT_EQ(work.views, 1);
  std::string error;
  EXPECT_EQ(postfx::detail::checkObjectCausticsWork(create, frame, sunOnly(), error),
            postfx::Result::Ok);
  // A budget one short of the work refuses it, naming the budget and the count.
  create.casterTriangleBudget = 2199;
  EXPECT_EQ(postfx::detail::checkObjectCausticsWork(create, frame, sunOnly(), error),
            postfx::Result::InvalidArgument);
  EXPECT_NE(error.find("2200 triangles"), std::string::npos) << error;
  EXPECT_NE(error.find("CreateDesc.casterTriangleBudget = 2199"), std::string::npos) << error;
  create.casterTriangleBudget = 2200;
  create.splatBudget = 65535;
  EXPECT_EQ(postfx::detail::checkObjectCausticsWork(create, frame, sunOnly(), error),
            postfx::Result::InvalidArgument);
  EXPECT_NE(error.find("65536 splats this frame (gridSize 256 squared, 1 view)"), std::string::npos)
      << error;
  // Dispersion traces each colour alone: three splats a ray.
  create.features = postfx::Feature::ObjectCaustics | postfx::Feature::Dispersion;
  create.splatBudget = 3 * 65536 - 1;
  std::vector<postfx::CasterMesh> dispersed = casters;
  dispersed[1].material.dispersion = 1.0f;
  frame.objectCaustics.casters = dispersed.data();
  EXPECT_EQ(objectCausticsWork(create, frame, sunOnly()).splats, 3 * 65536);
  EXPECT_EQ(postfx::detail::checkObjectCausticsWork(create, frame, sunOnly(), error),
            postfx::Result::InvalidArgument);
  EXPECT_NE(error.find("x3 for dispersion"), std::string::npos) << error;
}

// 64 casters of 2^31 - 1 indices each (every one valid for a host whose buffers hold them):
// 9.2e10 triangle draws a frame, refused up front; the sum saturates rather than wraps.
TEST(PostfxObjectCausticsWork, TheLargestCasterSetIsRefusedNotDrawn) {
  const std::vector<postfx::CasterMesh> casters(postfx::kMaxCasters,
                                                caster(std::numeric_limits<std::int32_t>::max()));
  postfx::FrameDesc frame;
  frame.objectCaustics.casters = casters.data();
  frame.objectCaustics.casterCount = postfx::kMaxCasters;
  postfx::CreateDesc create;
  create.features = postfx::Feature::ObjectCaustics;
  EXPECT_EQ(objectCausticsWork(create, frame, sunOnly()).triangles,
            std::int64_t(64) * 2 * (std::numeric_limits<std::int32_t>::max() / 3));
  std::string error;
  EXPECT_EQ(postfx::detail::checkObjectCausticsWork(create, frame, sunOnly(), error),
            postfx::Result::InvalidArgument);
  EXPECT_NE(error.find("casterTriangleBudget"), std::string::npos) << error;
  // Nothing to draw, nothing counted.
  EXPECT_EQ(objectCausticsWork(create, frame, FramePlan{}).triangles, 0);
}

}  // namespace
