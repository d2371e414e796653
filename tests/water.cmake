# Water module tests: CPU spectrum and reference math (unit), GPU ocean vs the reference,
# animation time, robustness and the GL state contract (gl).
postfx_add_test(water_unit_tests
  SOURCES unit/water_spectrum_test.cpp unit/water_reference_test.cpp
          unit/water_no_context_test.cpp
  LIBS water glkit)  # glkit: the no-context test asks glkit::hasCurrentContext directly
postfx_add_test(water_gl_tests
  SOURCES gl/water_ocean_test.cpp gl/water_robustness_test.cpp
  LIBS water GL)
