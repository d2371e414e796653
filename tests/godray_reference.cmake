# God-ray CPU reference (sample_app/reference): the plugin's god rays against the dense integral.
if(TARGET ocean_reference)
  postfx_add_test(godray_reference_tests
    SOURCES gl/godray_reference_test.cpp
    LIBS postfx_test_scene ocean_reference postfx gbuffer glm::glm postfx::epoxy
    GL LABELS reference)
endif()
