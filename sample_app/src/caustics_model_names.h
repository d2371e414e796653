#pragma once
// The names --caustics-model accepts, in one table so a new model is one line here (and its
// meaning in Options / plugin_setup.cpp).
#include <array>
#include <string_view>

namespace ocean {

struct CausticsModelName {
  std::string_view name;
  bool physical;  // Options::physicalCaustics
  bool listed;    // shown in --help and in the refusal; false for a former name kept working
};

inline constexpr std::array<CausticsModelName, 3> kCausticsModelNames{{
    {"ray-deviation", false, true},  // exp(-tau a^2) of the refracted ray's deviation (default)
    {"seed002", false, false},       // ray-deviation's former name
    {"physical", true, true},        // irradiance from the wavefront area ratio
}};

}  // namespace ocean
