#pragma once
// The sample's default scene, built once per test binary (building it loads the bundled glTF
// models; every test that renders the sample's presets shares it).
#include <gtest/gtest.h>

#include <string>

#include <scene_setup.h>

namespace sampletest {

inline const ocean_scene::Model& defaultScene() {
  static const ocean_scene::Model model = [] {
    ocean_scene::Model built;
    std::string error;
    EXPECT_TRUE(ocean::buildScene({}, built, error)) << error;
    return built;
  }();
  return model;
}

}  // namespace sampletest
