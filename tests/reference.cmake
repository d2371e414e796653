# CPU references (sample_app/reference): their own correctness on cases with known answers.
postfx_add_test(reference_unit_tests
  SOURCES unit/reference_seabed_test.cpp unit/reference_object_caustics_test.cpp
          unit/reference_local_light_test.cpp
  LIBS ocean_reference)

# The WavefrontAreaRatio caustics model: its own properties, its window as the
# caustics pass shows it, and its error against the seabed reference on the same read-back
# water texture.
postfx_add_test(postfx_wavefront_area_ratio_tests GL
  SOURCES gl/postfx_wavefront_area_ratio_mode_test.cpp
          gl/postfx_wavefront_area_ratio_reference_test.cpp gl/postfx_wavefront_area_ratio_window_test.cpp
  LIBS postfx_test_scene postfx ocean_reference water gbuffer glm::glm postfx::epoxy)
target_include_directories(postfx_wavefront_area_ratio_tests PRIVATE ${CMAKE_SOURCE_DIR}/postfx/src
  ${POSTFX_SHADER_ROOT})

# The caustics' water lookups on sloped receivers (along the light vs Feature::TriplanarWalls)
# against the seabed reference traced onto the same tilted planes, through the validation library (the report's rows run the same).
postfx_add_test(postfx_slope_lookup_tests GL
  SOURCES gl/postfx_slope_lookup_test.cpp
  LIBS ocean_validation water glm::glm postfx::epoxy)

# The validation library's sloped receiver (pixels to horizontal bins, the plane as the reference's height
# field, flat-water units) on known answers.
postfx_add_test(report_sloped_plane_tests
  SOURCES unit/report_sloped_plane_test.cpp
  LIBS ocean_validation)

# The ray-deviation caustics' pattern is no more streaked along the sun than traced light.
postfx_add_test(postfx_streak_tests GL
  SOURCES gl/postfx_streak_test.cpp
  LIBS ocean_validation water glm::glm postfx::epoxy)

# The TileIrradiance model (the default): flat water, where light may land, flux, and against
# converged light tracing on the flat seabed comparison (sample_app/validation); its spread keeps the flux.
postfx_add_test(postfx_tile_irradiance_tests GL
  SOURCES gl/postfx_tile_irradiance_test.cpp
          gl/postfx_tile_lookup_resolution_test.cpp gl/postfx_tile_spread_test.cpp
          gl/postfx_host_water_test.cpp gl/postfx_tile_footprint_test.cpp
          gl/postfx_tile_product_test.cpp
  LIBS postfx_test_scene ocean_validation postfx gbuffer water glm::glm postfx::epoxy)
target_include_directories(postfx_tile_irradiance_tests
  PRIVATE ${CMAKE_SOURCE_DIR}/postfx/src ${POSTFX_SHADER_ROOT})

# The traced frame reference (photon tracing against Embree triangles, density estimation per
# pixel) on scenes with known answers; CPU only.
postfx_add_test(reference_frame_tests
  SOURCES unit/reference_frame_test.cpp unit/reference_compare_test.cpp
          unit/pattern_comparison_test.cpp unit/reference_frame_casters_test.cpp
  LIBS ocean_reference)

# The traced frame reference's reflected light above the water (FrameTraceDesc::reflected):
# flat water's mirror light, a wave's reflected and refracted flux against the sun's, where none
# may land, its noise, determinism, and the refracted light untouched; CPU only.
postfx_add_test(reference_reflected_tests
  SOURCES unit/reference_frame_reflected_test.cpp
  LIBS ocean_reference)

# The traced frame reference's reflected light against the plugin's reflected caustics over a
# flat sea (same units).
postfx_add_test(reference_reflected_units_tests GL
  SOURCES gl/reference_reflected_units_test.cpp
  LIBS postfx_test_scene postfx ocean_reference gbuffer glm::glm postfx::epoxy)
target_include_directories(reference_reflected_units_tests PRIVATE ${CMAKE_SOURCE_DIR}/postfx/src
  ${POSTFX_SHADER_ROOT})

# The traced frame reference's light against the plugin's own added light (same units).
postfx_add_test(reference_frame_units_tests GL
  SOURCES gl/reference_frame_units_test.cpp
  LIBS postfx_test_scene postfx ocean_reference gbuffer glm::glm postfx::epoxy)
target_include_directories(reference_frame_units_tests PRIVATE ${CMAKE_SOURCE_DIR}/postfx/src
  ${POSTFX_SHADER_ROOT})
# The report's plot: panels per effect, Pareto front, label placement, both drawings.
postfx_add_test(report_plot_tests
  SOURCES unit/report_plot_test.cpp
  LIBS ocean_report)

# SunShadowMap's bias in metres and normal offset in texels on planes shadowing themselves
# (a wall, 60 degree slopes, a floor under a grazing sun), through the validation library's plane G-buffer.
postfx_add_test(postfx_shadow_bias_tests GL
  SOURCES gl/postfx_shadow_bias_test.cpp
  LIBS ocean_validation glm::glm postfx::epoxy)

# Point and spot lights' object caustics against the exact CPU ray tracing of the same
# glass sphere, through the validation library's host (light_caustic_run.h): focus, flux in air and under
# water, inverse square over 1-10 m, a spot cone's edge.
postfx_add_test(postfx_object_caustics_lights_accuracy_tests GL
  SOURCES gl/postfx_object_caustics_lights_accuracy_test.cpp
  LIBS ocean_validation ocean_reference glm::glm postfx::epoxy)

# The traced frame reference's reflected light against the plugin's reflected caustics over
# waves: their patterns on an underside and a wall.
postfx_add_test(reference_reflected_pattern_tests GL
  SOURCES gl/reference_reflected_pattern_test.cpp
  LIBS postfx_test_scene postfx ocean_reference gbuffer glm::glm postfx::epoxy)
target_include_directories(reference_reflected_pattern_tests PRIVATE ${CMAKE_SOURCE_DIR}/postfx/src
  ${POSTFX_SHADER_ROOT})

# The volume caustics (the light a glass sphere focuses, seen in the water) through the
# validation library's host (volume_caustic_run.h): the flux each ray scatters, IOR 1 against
# the unshadowed god rays, an occluder in front, feature off bit for bit, extreme views, and the
# cone against the traced beams at 640x360.
postfx_add_test(postfx_volume_caustics_tests GL
  SOURCES gl/postfx_volume_caustics_test.cpp
  LIBS ocean_validation ocean_reference glm::glm postfx::epoxy)
