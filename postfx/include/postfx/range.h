#pragma once
// A closed range [min, max] a setting must lie in. Each one is stated once, as a named constant
// beside its field; the field's comment names it and validation checks against it, so the
// documented range and the enforced one cannot drift. NaN is in no range.
namespace postfx {

template <typename T>
struct Range {
  T min, max;
  constexpr bool contains(T value) const { return value >= min && value <= max; }
};

}  // namespace postfx
