# postfx tests: CPU math/validation in unit/, the plugin against synthetic G-buffers in gl/.
# Both see the plugin's private headers (src/) and the shared GLSL/C++ headers, so they can
# evaluate the exact shader math on the CPU.
set(_postfx_private ${CMAKE_SOURCE_DIR}/postfx/src ${POSTFX_SHADER_ROOT})

postfx_add_test(postfx_unit_tests
  SOURCES unit/postfx_math_test.cpp unit/postfx_frame_test.cpp unit/postfx_godrays_math_test.cpp
          unit/postfx_no_context_test.cpp unit/postfx_wavefront_area_ratio_layout_test.cpp
          unit/postfx_object_caustics_frame_test.cpp unit/postfx_splat_test.cpp
          unit/postfx_object_caustics_light_frame_test.cpp unit/postfx_object_caustics_work_test.cpp
  LIBS postfx gbuffer glm::glm postfx::epoxy)
target_include_directories(postfx_unit_tests PRIVATE ${_postfx_private})

postfx_add_test(postfx_gl_tests
  SOURCES gl/postfx_state_test.cpp gl/postfx_bad_input_test.cpp
          gl/postfx_caustics_test.cpp gl/postfx_composition_test.cpp gl/postfx_stability_test.cpp
          gl/postfx_timing_test.cpp
          gl/postfx_bench_test.cpp gl/postfx_godrays_test.cpp gl/postfx_godrays_field_test.cpp
          gl/postfx_cascade_skip_test.cpp gl/postfx_caustics_lookup_test.cpp
          gl/postfx_refusal_test.cpp gl/postfx_local_water_test.cpp
          gl/postfx_tutorial_gbuffer_test.cpp
  LIBS postfx_test_scene postfx gbuffer glm::glm postfx::epoxy
  GL)
target_include_directories(postfx_gl_tests PRIVATE ${_postfx_private})

postfx_add_test(postfx_work_account_tests
  SOURCES gl/postfx_work_account_test.cpp
  LIBS postfx_test_scene postfx gbuffer glm::glm postfx::epoxy
  GL)
target_include_directories(postfx_work_account_tests PRIVATE ${_postfx_private})

postfx_add_test(postfx_reflected_caustics_tests
  SOURCES gl/postfx_reflected_caustics_test.cpp
  LIBS postfx_test_scene postfx gbuffer glm::glm postfx::epoxy
  GL)
target_include_directories(postfx_reflected_caustics_tests PRIVATE ${_postfx_private} ${CMAKE_CURRENT_SOURCE_DIR})

# The scene fixtures, the CPU ray tracer and the map measurements come from ocean_reference
# (sample_app/reference), which the report's object-caustics rows use too.
postfx_add_test(postfx_object_caustics_tests
  SOURCES gl/postfx_object_caustics_util.cpp
          gl/postfx_object_caustics_accuracy_test.cpp gl/postfx_object_caustics_contract_test.cpp
          gl/postfx_object_caustics_host_test.cpp gl/postfx_hostile_state_test.cpp
          gl/postfx_object_caustics_material_test.cpp gl/postfx_object_caustics_defaults_test.cpp
          gl/postfx_object_caustics_lights_contract_test.cpp gl/postfx_object_caustics_lights_util.cpp
          gl/postfx_object_caustics_lights_test.cpp gl/postfx_object_caustics_lights_stability_test.cpp
          gl/postfx_object_caustics_lights_cost_test.cpp gl/postfx_object_caustics_work_test.cpp
          gl/postfx_views_test.cpp gl/postfx_range_ends_test.cpp
  LIBS postfx_test_scene postfx ocean_reference gbuffer glm::glm postfx::epoxy
  GL)
target_include_directories(postfx_object_caustics_tests PRIVATE ${_postfx_private})

# The dispatch fuzz: a few thousand deterministic cases over every FrameDesc field
# group, the settings, the casters and the G-buffer texels, in four contexts.
postfx_add_test(postfx_fuzz_tests
  SOURCES fuzz/postfx_fuzz_test.cpp fuzz/postfx_views_fuzz_test.cpp
          gl/postfx_object_caustics_util.cpp
  LIBS postfx_test_scene postfx ocean_reference gbuffer glm::glm postfx::epoxy
  GL LABELS fuzz)
target_include_directories(postfx_fuzz_tests PRIVATE ${_postfx_private} ${CMAKE_CURRENT_SOURCE_DIR}/gl)
