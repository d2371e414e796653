#include "object_caustics/object_caustics_work.h"

#include <limits>

#include "object_caustics/object_caustics_light_frame.h"

namespace postfx::detail {
namespace {

constexpr std::int64_t kMax = std::numeric_limits<std::int64_t>::max();

std::int64_t add(std::int64_t a, std::int64_t b) {
  return a > kMax - b ? kMax : a + b;
}
std::int64_t mul(std::int64_t a, std::int64_t b) {
  return b != 0 && a > kMax / b ? kMax : a * b;
}

// Triangles of one caster as drawn (indexCount / 3, or vertexCount / 3).
std::int64_t casterTriangles(const CasterMesh& m) {
  return (m.indexBuffer != 0 ? m.indexCount : m.vertexCount) / 3;
}

// The casters a view draws, twice each: the front faces' map and the back faces'.
std::int64_t viewTriangles(const ObjectCausticsFrame& o, std::uint64_t mask) {
  std::int64_t sum = 0;
  for (int c = 0; c < o.casterCount && c < kMaxCasters; ++c) {
    if ((mask >> c) & 1u) sum = add(sum, mul(2, casterTriangles(o.casters[c])));
  }
  return sum;
}

// Whether a caster splits its rays per colour channel this frame (as the pass's block says).
bool dispersed(const CreateDesc& create, const ObjectCausticsFrame& o) {
  if (!hasFeature(create.features, Feature::Dispersion)) return false;
  for (int c = 0; c < o.casterCount; ++c) {
    const CasterMaterial& m = o.casters[c].material;
    if (m.type == CasterMaterialType::Refractive &&
        (double(m.ior) - 1.0) * double(m.dispersion) > 0.0)
      return true;
  }
  return false;
}

}  // namespace

ObjectCausticsWork objectCausticsWork(const CreateDesc& create, const FrameDesc& frame,
                                      const FramePlan& plan) {
  ObjectCausticsWork work;
  const ObjectCausticsFrame& o = frame.objectCaustics;
  if (!plan.objectMaps() || o.casters == nullptr) return work;
  const std::int64_t grid = o.settings.gridSize;
  const std::int64_t splatsPerView = mul(mul(grid, grid), dispersed(create, o) ? 3 : 1);
  if (plan.objects) {
    work.triangles = viewTriangles(o, ~std::uint64_t(0));
    work.splats = splatsPerView;
    work.views = 1;
  }
  for (int k = 0; k < plan.lightCount; ++k) {
    ObjectLightFrame view;
    fitLocalLightFrame(frame, plan.lights[static_cast<std::size_t>(k)], view);
    work.triangles = add(work.triangles, viewTriangles(o, view.casters));
    work.splats = add(work.splats, splatsPerView);
    ++work.views;
  }
  return work;
}

Result checkObjectCausticsWork(const CreateDesc& create, const FrameDesc& frame,
                               const FramePlan& plan, std::string& error) {
  const ObjectCausticsWork work = objectCausticsWork(create, frame, plan);
  const std::string views = std::to_string(work.views) + (work.views == 1 ? " view" : " views");
  if (work.triangles > create.casterTriangleBudget) {
    error =
        "objectCaustics: the casters draw " + std::to_string(work.triangles) +
        " triangles this frame (front and back faces, " + views +
        "), over CreateDesc.casterTriangleBudget = " + std::to_string(create.casterTriangleBudget) +
        "; refused before drawing (fewer or coarser casters, fewer lights, or a larger "
        "budget)";
    return Result::InvalidArgument;
  }
  if (work.splats > create.splatBudget) {
    error = "objectCaustics: " + std::to_string(work.splats) + " splats this frame (gridSize " +
            std::to_string(frame.objectCaustics.settings.gridSize) + " squared" +
            (dispersed(create, frame.objectCaustics) ? ", x3 for dispersion, " : ", ") + views +
            "), over CreateDesc.splatBudget = " + std::to_string(create.splatBudget) +
            "; refused before drawing (a smaller objectCaustics.settings.gridSize, fewer "
            "lights, or a larger budget)";
    return Result::InvalidArgument;
  }
  return Result::Ok;
}

}  // namespace postfx::detail
