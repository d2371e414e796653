// The test-only entry points of <postfx/testing.h>: the plugin's intermediate textures and the
// god rays' sampling switches. Like the public entry points, none throws or prints.
#include <postfx/testing.h>

#include "core/context.h"

namespace postfx {

namespace testing {

LightCausticMap lightCausticMap(const Context& context) noexcept {
  LightCausticMap map;
  map.texture = context.objectCaustics.lightMapTexture();
  map.size = context.objectCaustics.lightMapSize();
  map.worldToMapClip = context.objectCaustics.lightMapClip();
  return map;
}

GlName rawCausticTexture(const Context& context) noexcept {
  return context.defaultView.caustics.raw.id();
}

GlName rawCausticTexture(const View& view) noexcept {
  return view.caustics.raw.id();
}

std::uint64_t viewAllocatedBytes(const View& view) noexcept {
  return view.allocatedBytes();
}

CausticIrradianceInfo causticIrradiance(const Context& context) noexcept {
  CausticIrradianceInfo info;
  const detail::WavefrontAreaRatioLayout& l = context.wavefrontAreaRatio.layout();
  info.texture = context.wavefrontAreaRatio.texture();
  if (info.texture == 0) return info;
  info.resolution = l.resolution;
  info.layers = l.layers;
  info.windowOrigin = l.windowOrigin;
  info.windowSize = l.windowSize;
  for (int k = 0; k < l.layers && k < detail::kMaxWavefrontAreaRatioLayers; ++k)
    info.layerDepth[k] = static_cast<float>(l.depth[k]);
  return info;
}

Result setGodRaySampling(Context& context, GodRaySampling sampling) noexcept {
  if (sampling != GodRaySampling::WorldGrid && sampling != GodRaySampling::UniformAlongRay) {
    context.error = "setGodRaySampling: not a GodRaySampling";
    return Result::InvalidArgument;
  }
  context.error.clear();
  context.godRaySampling = sampling;
  return Result::Ok;
}

Result setGodRayUniformPhase(Context& context, float phase) noexcept {
  if (!(phase >= 0.0f && phase < 1.0f)) {
    context.error = "setGodRayUniformPhase: phase must be in [0, 1)";
    return Result::InvalidArgument;
  }
  context.error.clear();
  context.godRayUniformPhase = phase;
  return Result::Ok;
}

}  // namespace testing

}  // namespace postfx
