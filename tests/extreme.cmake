# Extreme-case suite: a table of stiff inputs (extreme/extreme_table.cpp) run on every pass,
# one ctest entry per (row, pass). It reuses the postfx GL test scene and the water module.
set(_extreme_private ${CMAKE_SOURCE_DIR}/postfx/src ${POSTFX_SHADER_ROOT}
    ${CMAKE_CURRENT_SOURCE_DIR}/gl)
postfx_add_test(extreme_case_tests
  SOURCES extreme/extreme_case.cpp extreme/extreme_table.cpp extreme/extreme_runner.cpp
          extreme/extreme_bounds.cpp extreme/extreme_suite_test.cpp
  LIBS postfx_test_scene postfx gbuffer water glm::glm postfx::epoxy
  GL LABELS extreme)
target_include_directories(extreme_case_tests PRIVATE ${_extreme_private})
