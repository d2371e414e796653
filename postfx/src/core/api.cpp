// The public entry points: validation first, GL work only once everything is known good, and
// no exception ever crossing the API boundary.
#include <postfx/postfx.h>
#include <postfx/testing.h>

#include <glkit/current_context.h>

#include <array>
#include <memory>
#include <new>

#include "core/context.h"
#include "core/frame_pipeline.h"
#include "core/validation.h"

namespace postfx {
namespace {

thread_local std::string createError;

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
    if (hasFeature(desc.features, Feature::ObjectCaustics)) {
      r = context->objectCaustics.init(detail::shaderDefines(desc), desc.maxLocalLights,
                                       createError);
      if (r != Result::Ok) return r;
      present[int(Pass::ObjectCaustics)] = true;
    }
    context->timers.init(
        present, hasFeature(desc.features, Feature::ObjectCaustics) ? desc.maxLocalLights : 0);
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
  try {
    context.error.clear();
    if (!glkit::hasCurrentContext()) {
      context.error = "dispatch: no current GL context on this thread";
      return Result::NoContext;
    }
    return detail::dispatchFrame(context, desc);
  } catch (const std::bad_alloc&) {
    context.error = "out of memory";
    return Result::OutOfMemory;
  } catch (...) {
    context.error = "internal error";
    return Result::GlError;
  }
}

void destroy(Context* context) noexcept {
  // Without a current context the GL objects cannot be deleted and trying would abort inside
  // epoxy; they are leaked instead (they die with the GL context that owns them).
  if (context != nullptr && glkit::hasCurrentContext()) delete context;
}

const char* lastError(const Context* context) noexcept {
  return context != nullptr ? context->error.c_str() : createError.c_str();
}

const FrameStats& stats(const Context& context) noexcept {
  return context.timers.stats();
}

ObjectCausticMap objectCausticMap(const Context& context) noexcept {
  return context.objectCaustics.map();
}

}  // namespace postfx
