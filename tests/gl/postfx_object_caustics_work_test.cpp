// The object caustics' work budget through dispatch: a caster set over
// CreateDesc::casterTriangleBudget or a grid over ::splatBudget is refused with
// InvalidArgument before anything is drawn, and the same frame within the budget draws.
#include <gtest/gtest.h>

#include <string>

#include "gl_fixture.h"
#include "postfx_object_caustics_util.h"

namespace {

using namespace postfxtest;
using postfx::Result;

class PostfxObjectCausticsWorkTest : public testsupport::GlTest {};

ContextPtr contextWith(std::int64_t triangles, std::int64_t splats) {
  postfx::CreateDesc desc;
  desc.features = postfx::Feature::ObjectCaustics;
  desc.casterTriangleBudget = triangles;
  desc.splatBudget = splats;
  postfx::Context* raw = nullptr;
  EXPECT_EQ(postfx::create(desc, raw), Result::Ok) << postfx::lastError(nullptr);
  return ContextPtr(raw);
}

TEST_F(PostfxObjectCausticsWorkTest, OverTheBudgetIsRefusedBeforeDrawing) {
  ObjectHost host(sunAt(20.0, 30.0));
  const GlMesh mesh = makeSphereMesh(1.0, 32, 16);
  postfx::CasterMaterial glass;
  const postfx::CasterMesh caster = mesh.caster(translation({0.0, 1.5, 0.0}), glass);
  const std::int64_t drawn = 2 * (caster.indexCount / 3);  // front and back faces, the sun
  postfx::ObjectCausticsSettings s;
  s.gridSize = 128;
  const postfx::FrameDesc frame = host.frame(&caster, 1, s);
  const int w = host.scene.spec().width, h = host.scene.spec().height;
  const glm::vec4 marker(0.25f);
  struct Budget {
    std::int64_t triangles, splats;
    Result expected;
    const char* named;
  };
  for (const Budget& b :
       {Budget{drawn - 1, 128 * 128, Result::InvalidArgument, "casterTriangleBudget"},
        Budget{drawn, 128 * 128 - 1, Result::InvalidArgument, "splatBudget"},
        Budget{drawn, 128 * 128, Result::Ok, ""}}) {
    auto fx = contextWith(b.triangles, b.splats);
    host.scene.clearTarget(marker);
    EXPECT_EQ(postfx::dispatch(*fx, frame), b.expected) << postfx::lastError(fx.get());
    const std::string message = postfx::lastError(fx.get());
    int changed = 0;
    for (const glm::vec4& v : readRgba(host.scene.target, w, h)) changed += v != marker ? 1 : 0;
    if (b.expected == Result::Ok) {
      EXPECT_GT(changed, 100) << "within the budget the caster's light is added";
    } else {
      EXPECT_NE(message.find(b.named), std::string::npos) << message;
      EXPECT_EQ(changed, 0) << "nothing drawn before the refusal";
      EXPECT_EQ(postfx::objectCausticMap(*fx).texture, 0u);
    }
  }
  postfx::CreateDesc bad;
  bad.features = postfx::Feature::ObjectCaustics;
  bad.splatBudget = 0;
  postfx::Context* raw = nullptr;
  EXPECT_EQ(postfx::create(bad, raw), Result::InvalidArgument);
  EXPECT_NE(std::string(postfx::lastError(nullptr)).find("CreateDesc.splatBudget"),
            std::string::npos);
}

}  // namespace
