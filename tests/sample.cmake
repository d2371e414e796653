postfx_add_test(sample_render_tests GL
  SOURCES gl/sample_render_test.cpp
  LIBS ocean_host)
postfx_add_test(sample_physical_light_tests GL
  SOURCES gl/sample_physical_light_test.cpp
  LIBS ocean_host)
postfx_add_test(sample_cli_tests
  SOURCES unit/sample_cli_test.cpp
  LIBS ocean_host nlohmann_json::nlohmann_json)
target_compile_definitions(sample_cli_tests PRIVATE
  OCEAN_SAMPLE_EXE="$<TARGET_FILE:ocean_sample>"
  OCEAN_ASSETS="${CMAKE_BINARY_DIR}/assets")
add_dependencies(sample_cli_tests ocean_sample)
postfx_add_test(sample_model_tests
  SOURCES unit/sample_model_placement_test.cpp
  LIBS ocean_host)
# The view in a window on its own Xvfb display against a headless render; skipped (with the
# reason) where Xvfb is missing or cannot start.
postfx_add_test(sample_view_window_tests
  SOURCES unit/sample_view_window_test.cpp
  LIBS PkgConfig::OIIO
  LABELS window)
target_compile_definitions(sample_view_window_tests PRIVATE
  OCEAN_SAMPLE_EXE="$<TARGET_FILE:ocean_sample>")
add_dependencies(sample_view_window_tests ocean_sample)
postfx_add_test(sample_live_settings_tests GL
  SOURCES gl/sample_live_settings_test.cpp
  LIBS ocean_host)
postfx_add_test(sample_view_flags_tests GL
  SOURCES gl/sample_view_flags_test.cpp
  LIBS ocean_host ocean_reference)
# A flicker test per pass, and the plugin's change against its references'.
postfx_add_test(sample_stability_tests GL
  SOURCES gl/sample_stability_test.cpp
  LIBS ocean_lab)
postfx_add_test(sample_glass_refraction_tests GL
  SOURCES gl/sample_glass_refraction_test.cpp
  LIBS ocean_host)
# The pool's ripple simulation: wave speed, volume, rest, slopes, a sphere's volume, extremes.
postfx_add_test(sample_ripple_simulation_tests GL
  SOURCES gl/sample_ripple_simulation_test.cpp
  LIBS ocean_host)
# The host's local water: the pool's surface shows its ripples only inside it; the plugin's
# feature and region.
postfx_add_test(sample_local_water_render_tests GL
  SOURCES gl/sample_local_water_render_test.cpp
  LIBS ocean_host)
# The pool preset: its script's determinism (CPU), and headless renders of it (the CLI).
postfx_add_test(sample_pool_script_tests
  SOURCES unit/sample_pool_script_test.cpp
  LIBS ocean_host)
postfx_add_test(sample_water_pick_tests
  SOURCES unit/sample_water_pick_test.cpp
  LIBS ocean_host)
postfx_add_test(sample_pool_cli_tests
  SOURCES unit/sample_pool_cli_test.cpp
  LIBS PkgConfig::OIIO)
target_compile_definitions(sample_pool_cli_tests PRIVATE
  OCEAN_SAMPLE_EXE="$<TARGET_FILE:ocean_sample>")
add_dependencies(sample_pool_cli_tests ocean_sample)
# The harbour preset: its receivers, window and scene (CPU, with the command line's flags), and
# what the plugin is handed and how the sample draws it (GL).
postfx_add_test(sample_harbour_tests
  SOURCES unit/sample_harbour_test.cpp
  LIBS ocean_host ocean_lab)
postfx_add_test(sample_harbour_render_tests GL
  SOURCES gl/sample_harbour_render_test.cpp
  LIBS ocean_host)
# The pool against its traced reference at 640x360, the pattern alone (about 2 minutes).
postfx_add_test(sample_pool_reference_tests
  SOURCES unit/sample_pool_reference_test.cpp)
target_compile_definitions(sample_pool_reference_tests PRIVATE
  OCEAN_SAMPLE_EXE="$<TARGET_FILE:ocean_sample>")
add_dependencies(sample_pool_reference_tests ocean_sample)
# The cost model's terms, its GPU table and the NIR counts it reads (docs/gpu_cost.md).
postfx_add_test(sample_cost_model_tests
  SOURCES unit/cost_model_test.cpp
  LIBS ocean_cost_model)
# bench --work on every feature: counted work within each shader's statement, estimates labelled.
postfx_add_test(sample_work_bench_tests
  SOURCES unit/sample_work_bench_test.cpp
  LIBS nlohmann_json::nlohmann_json)
target_compile_definitions(sample_work_bench_tests PRIVATE
  OCEAN_SAMPLE_EXE="$<TARGET_FILE:ocean_sample>")
target_include_directories(sample_work_bench_tests PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/support)
add_dependencies(sample_work_bench_tests ocean_sample)
