#include <postfx/conventions.h>

namespace postfx {

const char* toString(DepthConvention convention) noexcept {
  switch (convention) {
    case DepthConvention::ReverseZ:
      return "ReverseZ";
    case DepthConvention::ForwardZeroToOne:
      return "ForwardZeroToOne";
    case DepthConvention::ForwardNegOneToOne:
      return "ForwardNegOneToOne";
  }
  return "unknown";
}

const char* toString(NormalEncoding encoding) noexcept {
  switch (encoding) {
    case NormalEncoding::Octahedral:
      return "Octahedral";
    case NormalEncoding::WorldXyz:
      return "WorldXyz";
    case NormalEncoding::WorldXyzUnorm:
      return "WorldXyzUnorm";
  }
  return "unknown";
}

const char* toString(IndexType type) noexcept {
  switch (type) {
    case IndexType::UnsignedByte:
      return "UnsignedByte";
    case IndexType::UnsignedShort:
      return "UnsignedShort";
    case IndexType::UnsignedInt:
      return "UnsignedInt";
  }
  return "unknown";
}

}  // namespace postfx
