#pragma once
// The public convention enums against the values the shaders and the gbuffer module use, and
// the range checks validation runs on them (an enum class can still hold any integer).
#include <gbuffer/codec.h>
#include <postfx/conventions.h>

namespace postfx::detail {

static_assert(static_cast<int>(DepthConvention::ReverseZ) == gbuffer::shared::DEPTH_REVERSE_Z);
static_assert(static_cast<int>(DepthConvention::ForwardZeroToOne) ==
              gbuffer::shared::DEPTH_FORWARD_ZERO_ONE);
static_assert(static_cast<int>(DepthConvention::ForwardNegOneToOne) ==
              gbuffer::shared::DEPTH_FORWARD_NEG_ONE);
static_assert(static_cast<int>(NormalEncoding::Octahedral) == gbuffer::shared::NORMAL_OCTAHEDRAL);
static_assert(static_cast<int>(NormalEncoding::WorldXyz) == gbuffer::shared::NORMAL_XYZ);
static_assert(static_cast<int>(NormalEncoding::WorldXyzUnorm) == gbuffer::shared::NORMAL_XYZ_UNORM);

inline bool isDepthConvention(DepthConvention c) {
  return c == DepthConvention::ReverseZ || c == DepthConvention::ForwardZeroToOne ||
         c == DepthConvention::ForwardNegOneToOne;
}
inline bool isNormalEncoding(NormalEncoding e) {
  return e == NormalEncoding::Octahedral || e == NormalEncoding::WorldXyz ||
         e == NormalEncoding::WorldXyzUnorm;
}
inline gbuffer::DepthConvention toGbuffer(DepthConvention c) {
  return static_cast<gbuffer::DepthConvention>(c);
}

}  // namespace postfx::detail
