postfx_add_test(gbuffer_unit_tests
  SOURCES unit/gbuffer_reconstruction_test.cpp unit/gbuffer_normal_codec_test.cpp
  LIBS gbuffer)
postfx_add_test(gbuffer_gl_tests GL
  SOURCES gl/gbuffer_shader_mirror_test.cpp gl/gbuffer_targets_test.cpp
  LIBS gbuffer)
embed_shaders(gbuffer_gl_tests NAMESPACE gbuffer_test FILES
  shared/common.h shared/gbuffer_codec.h gbuffer/test_reconstruct.comp)
