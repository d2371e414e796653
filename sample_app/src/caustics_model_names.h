#pragma once
// The names --caustics-model accepts, in one table so a new model is one line here (and its
// meaning in Options / plugin_setup.cpp).
#include <array>
#include <string_view>

namespace ocean {

struct CausticsModelName {
  std::string_view name;
  bool physical;      // Options::physicalCaustics
  bool rayDeviation;  // Options::rayDeviationCaustics
  bool listed;        // shown in --help and in the refusal; false for a former name kept working
};

inline constexpr std::array<CausticsModelName, 5> kCausticsModelNames{{
    {"tile", false, false, true},                 // per-cascade tile irradiance (the default)
    {"ray-deviation", false, true, true},         // exp(-tau a^2) of the refracted ray's deviation
    {"seed002", false, true, false},              // ray-deviation's former name
    {"wavefront-area-ratio", true, false, true},  // irradiance window from the area ratio
    {"physical", true, false, false},             // wavefront-area-ratio's former name
}};

}  // namespace ocean
