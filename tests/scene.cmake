# Scene module tests (CPU only): procedural scene contracts, glTF round trip and loader
# robustness. The generated assets come from the ocean_assets target via ocean_asset_dir.
if(TARGET ocean_scene)
  postfx_add_test(scene_unit_tests
    SOURCES unit/scene_procedural_test.cpp unit/scene_harbour_test.cpp
            unit/scene_gltf_roundtrip_test.cpp
            unit/scene_gltf_errors_test.cpp
            unit/scene_gltf_hostile_test.cpp unit/scene_gltf_features_test.cpp
            unit/scene_gltf_fuzz_test.cpp unit/scene_gltf_draco_test.cpp
            unit/scene_gltf_meshopt_test.cpp unit/scene_gltf_texture_test.cpp
            unit/scene_gltf_budget_test.cpp unit/scene_gltf_limits_test.cpp
            unit/scene_gltf_messages_test.cpp unit/gltf_hostile_corpus.cpp
    LIBS ocean_scene ocean_asset_dir TinyGLTF::TinyGLTF draco::draco
         meshoptimizer::meshoptimizer PkgConfig::OIIO)
endif()

# The glTF loader's fuzz target: seeded mutations of the unit test's seeds
# and of the regression corpus for OCEAN_GLTF_FUZZ_SECONDS (default 45 s); `ctest -L fuzz`.
if(TARGET ocean_scene)
  postfx_add_test(scene_gltf_fuzz_tests
    SOURCES fuzz/scene_gltf_fuzz_test.cpp unit/gltf_hostile_corpus.cpp
    LIBS ocean_scene TinyGLTF::TinyGLTF draco::draco meshoptimizer::meshoptimizer PkgConfig::OIIO
    LABELS fuzz)
  target_include_directories(scene_gltf_fuzz_tests PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/unit)
endif()
