// The printable names of the public enums: the timers' pass names and the results' names.
#include <postfx/postfx.h>

namespace postfx {

const char* toString(Pass pass) noexcept {
  switch (pass) {
    case Pass::WavefrontAreaRatio:
      return "wavefront_area_ratio";
    case Pass::TileIrradiance:
      return "tile_irradiance";
    case Pass::Floor:
      return "floor";
    case Pass::Caustics:
      return "caustics";
    case Pass::GodRays:
      return "god_rays";
    case Pass::ObjectCaustics:
      return "object_caustics";
    case Pass::LocalWater:
      return "local_water";
    case Pass::ReflectedCaustics:
      return "reflected_caustics";
  }
  return "unknown";
}

const char* toString(Result result) noexcept {
  switch (result) {
    case Result::Ok:
      return "Ok";
    case Result::InvalidArgument:
      return "InvalidArgument";
    case Result::MissingTexture:
      return "MissingTexture";
    case Result::UnsupportedFormat:
      return "UnsupportedFormat";
    case Result::SizeMismatch:
      return "SizeMismatch";
    case Result::ShaderCompileFailed:
      return "ShaderCompileFailed";
    case Result::GlError:
      return "GlError";
    case Result::OutOfMemory:
      return "OutOfMemory";
    case Result::NoContext:
      return "NoContext";
  }
  return "Unknown";
}

}  // namespace postfx
