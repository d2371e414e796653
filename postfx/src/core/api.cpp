// The public entry points: validation first, GL work only once everything is known good, and
// no exception ever crossing the API boundary.
#include <postfx/postfx.h>
#include <postfx/testing.h>

#include <glkit/current_context.h>

#include <array>
#include <memory>
#include <new>
#include <string>

#include "core/context.h"
#include "core/frame_pipeline.h"
#include "core/validation.h"

namespace postfx {
namespace {

thread_local std::string createError;

// stats(context): the shared passes from the context's timers, the per-view ones from its own
// view's. Kept current after every call that can change them, so that a reference a host holds
// reads the latest numbers, as it always has.
void mergeStats(Context& context) {
  FrameStats& merged = context.mergedStats;
  merged = context.timers.stats();
  const FrameStats& own = context.defaultView.timers.stats();
  for (int p = 0; p < kPassCount; ++p)
    if (detail::isViewPass(Pass(p))) merged.passes[p] = own.passes[p];
  if (!context.desc.workAccount) return;
  std::vector<WorkStep>& steps = context.mergedSteps;
  try {
    steps = context.timers.work().steps();
    const std::vector<WorkStep>& view = context.defaultView.timers.work().steps();
    steps.insert(steps.end(), view.begin(), view.end());
  } catch (const std::bad_alloc&) {
    steps.clear();  // the account is a diagnostic: never a reason to fail the host's frame
  }
}

// A call on `context` (named `call` in its messages): the error cleared, a current GL context
// required (any GL call through epoxy without one aborts the process), nothing thrown out.
template <typename Work>
Result guarded(Context& context, const char* call, Work&& work) noexcept {
  try {
    context.error.clear();
    if (!glkit::hasCurrentContext()) {
      context.error = std::string(call) + ": no current GL context on this thread";
      return Result::NoContext;
    }
    return work();
  } catch (const std::bad_alloc&) {
    context.error = "out of memory";
    return Result::OutOfMemory;
  } catch (...) {
    context.error = "internal error";
    return Result::GlError;
  }
}

// A dispatch: guarded, and the stats merged whatever it returned.
template <typename Work>
Result guardedDispatch(Context& context, Work&& work) noexcept {
  const Result r = guarded(context, "dispatch", work);
  mergeStats(context);
  return r;
}

}  // namespace

Result create(const CreateDesc& desc, Context*& out) noexcept {
  out = nullptr;
  try {
    createError.clear();
    Result r = detail::validateCreateDesc(desc, createError);
    if (r != Result::Ok) return r;
    // Any GL call through epoxy without a context aborts the process: refuse instead.
    if (!glkit::hasCurrentContext()) {
      createError = "create: no current GL context on this thread";
      return Result::NoContext;
    }
    auto context = std::make_unique<Context>();
    context->desc = desc;
    r = context->caustics.init(desc, createError);
    if (r != Result::Ok) return r;
    std::array<bool, kPassCount> present{};
    present[int(Pass::Caustics)] = hasFeature(desc.features, Feature::Caustics);
    present[int(Pass::Floor)] = hasFeature(desc.features, testing::BenchmarkFloor);
    // TileIrradiance needs no feature of its own: its pre-pass exists wherever caustics or god
    // rays (which read its field) do.
    present[int(Pass::TileIrradiance)] =
        hasFeature(desc.features, Feature::Caustics) || hasFeature(desc.features, Feature::GodRays);
    if (hasFeature(desc.features, Feature::GodRays)) {
      r = context->godRays.init(detail::shaderDefines(desc), createError);
      if (r != Result::Ok) return r;
      present[int(Pass::GodRays)] = true;
    }
    if (hasFeature(desc.features, Feature::WavefrontAreaRatio)) {
      r = context->wavefrontAreaRatio.init(detail::shaderDefines(desc), createError);
      if (r != Result::Ok) return r;
      present[int(Pass::WavefrontAreaRatio)] = true;
    }
    if (hasFeature(desc.features, Feature::LocalWater)) {
      r = context->localWater.init(detail::shaderDefines(desc), createError);
      if (r != Result::Ok) return r;
      present[int(Pass::LocalWater)] = true;
    }
    if (hasFeature(desc.features, Feature::ReflectedCaustics)) {
      r = context->reflected.init(desc, createError);
      if (r != Result::Ok) return r;
      present[int(Pass::ReflectedCaustics)] = true;
    }
    if (hasFeature(desc.features, Feature::ObjectCaustics)) {
      r = context->objectCaustics.init(detail::shaderDefines(desc), desc.maxLocalLights,
                                       hasFeature(desc.features, Feature::VolumeCaustics),
                                       createError);
      if (r != Result::Ok) return r;
      present[int(Pass::ObjectCaustics)] = true;
    }
    // The shared passes are timed once per frame by the context, the others by each view.
    context->present = present;
    std::array<bool, kPassCount> shared{};
    for (int p = 0; p < kPassCount; ++p) shared[p] = present[p] && !detail::isViewPass(Pass(p));
    context->timers.init(
        shared, hasFeature(desc.features, Feature::ObjectCaustics) ? desc.maxLocalLights : 0);
    context->timers.initWork(desc.workAccount, hasFeature(desc.features, testing::CountShaderWork),
                             hasFeature(desc.features, testing::TimeEachStep));
    detail::initView(context->defaultView, desc, present);
    mergeStats(*context);
    out = context.release();
    return Result::Ok;
  } catch (const std::bad_alloc&) {
    createError = "out of memory";
    return Result::OutOfMemory;
  } catch (...) {
    createError = "internal error";
    return Result::GlError;
  }
}

Result dispatch(Context& context, const FrameDesc& desc) noexcept {
  return guardedDispatch(context, [&] {
    ViewDesc view;
    view.view = &context.defaultView;
    view.depth = desc.depth;
    view.normal = desc.normal;
    view.albedo = desc.albedo;
    view.target = desc.target;
    view.camera = desc.camera;
    return detail::dispatchFrame(context, desc, {&view, 1}, false);
  });
}

void destroy(Context* context) noexcept {
  // Without a current context the GL objects cannot be deleted and trying would abort inside
  // epoxy; they are leaked instead (they die with the GL context that owns them).
  if (context != nullptr && glkit::hasCurrentContext()) delete context;
}

const char* lastError(const Context* context) noexcept {
  return context != nullptr ? context->error.c_str() : createError.c_str();
}

Result dispatch(Context& context, const FrameDesc& frame, const ViewDesc* views,
                int viewCount) noexcept {
  return guardedDispatch(context, [&] {
    if (views == nullptr && viewCount != 0) {
      context.error = "views is null but viewCount is " + std::to_string(viewCount);
      return Result::InvalidArgument;
    }
    if (viewCount < 0 || viewCount > kMaxViews) {
      context.error = "viewCount is " + std::to_string(viewCount) + ", must be in [1, " +
                      std::to_string(kMaxViews) + "]";
      return Result::InvalidArgument;
    }
    return detail::dispatchFrame(context, frame, {views, static_cast<std::size_t>(viewCount)},
                                 true);
  });
}

Result createView(Context& context, View*& out) noexcept {
  out = nullptr;
  return guarded(context, "createView", [&] {
    auto view = std::make_unique<View>();
    detail::initView(*view, context.desc, context.present);
    context.views.push_back(std::move(view));
    out = context.views.back().get();
    return Result::Ok;
  });
}

void destroyView(Context& context, View* view) noexcept {
  auto& views = context.views;
  for (auto it = views.begin(); it != views.end(); ++it) {
    if (it->get() != view) continue;
    // Without a current context its GL objects cannot be deleted (epoxy would abort): leaked.
    if (!glkit::hasCurrentContext()) (void)it->release();
    views.erase(it);
    return;
  }
}

const FrameStats& stats(const View& view) noexcept {
  return view.timers.stats();
}

const FrameStats& stats(const Context& context) noexcept {
  return context.mergedStats;
}

WorkSteps workSteps(const Context& context) noexcept {
  return {context.mergedSteps.data(), static_cast<int>(context.mergedSteps.size())};
}

WorkSteps workSteps(const View& view) noexcept {
  const std::vector<WorkStep>& steps = view.timers.work().steps();
  return {steps.data(), static_cast<int>(steps.size())};
}

ObjectCausticMap objectCausticMap(const Context& context) noexcept {
  return context.objectCaustics.map();
}

}  // namespace postfx
