#pragma once
// An independent record of the GL state a host cares about, for "dispatch left everything as it
// was" tests. Deliberately wider than what the plugin touches, and written without reusing the
// plugin's guard, so the guard cannot hide its own omissions.
#include <epoxy/gl.h>

#include <map>
#include <string>
#include <vector>

namespace postfxtest {

using GlSnapshot = std::map<std::string, std::vector<long long>>;

// "name[index]", built by appending: GCC 12 warns falsely (-Wrestrict) on chained operator+.
inline std::string indexedName(const char* name, GLuint index) {
  std::string s(name);
  s += '[';
  s += std::to_string(index);
  s += ']';
  return s;
}

inline GlSnapshot snapshotGlState() {
  GlSnapshot s;
  auto ints = [&s](const char* name, GLenum pname, int count) {
    std::vector<GLint64> v(static_cast<size_t>(count) + 4, 0);
    glGetInteger64v(pname, v.data());
    s[name] = std::vector<long long>(v.begin(), v.begin() + count);
  };
  auto indexed = [&s](const char* name, GLenum pname, GLuint index, int count) {
    std::vector<GLint64> v(static_cast<size_t>(count) + 4, 0);
    glGetInteger64i_v(pname, index, v.data());
    s[indexedName(name, index)] = std::vector<long long>(v.begin(), v.begin() + count);
  };
  auto enabled = [&s](const char* name, GLenum cap) { s[name] = {glIsEnabled(cap)}; };
  ints("draw_framebuffer", GL_DRAW_FRAMEBUFFER_BINDING, 1);
  ints("read_framebuffer", GL_READ_FRAMEBUFFER_BINDING, 1);
  ints("renderbuffer", GL_RENDERBUFFER_BINDING, 1);
  for (GLuint i = 0; i < 16; ++i) {
    indexed("viewport", GL_VIEWPORT, i, 4);
    indexed("scissor_box", GL_SCISSOR_BOX, i, 4);
    s[indexedName("scissor_test", i)] = {glIsEnabledi(GL_SCISSOR_TEST, i)};
  }
  for (GLuint i = 0; i < 8; ++i) {
    s[indexedName("blend", i)] = {glIsEnabledi(GL_BLEND, i)};
    indexed("blend_src_rgb", GL_BLEND_SRC_RGB, i, 1);
    indexed("blend_dst_rgb", GL_BLEND_DST_RGB, i, 1);
    indexed("blend_src_alpha", GL_BLEND_SRC_ALPHA, i, 1);
    indexed("blend_dst_alpha", GL_BLEND_DST_ALPHA, i, 1);
    indexed("blend_eq_rgb", GL_BLEND_EQUATION_RGB, i, 1);
    indexed("blend_eq_alpha", GL_BLEND_EQUATION_ALPHA, i, 1);
    GLboolean mask[4] = {};
    glGetBooleani_v(GL_COLOR_WRITEMASK, i, mask);
    s[indexedName("color_mask", i)] = {mask[0], mask[1], mask[2], mask[3]};
  }
  auto floats = [&s](const char* name, GLenum pname, int count) {
    std::vector<GLfloat> v(static_cast<size_t>(count) + 4, 0.0f);
    glGetFloatv(pname, v.data());
    std::vector<long long> scaled;
    for (int i = 0; i < count; ++i) scaled.push_back(static_cast<long long>(double(v[i]) * 1e6));
    s[name] = scaled;
  };
  floats("blend_color", GL_BLEND_COLOR, 4);
  // Fixed-function state that changes what a draw writes (the host-state list).
  enabled("color_logic_op", GL_COLOR_LOGIC_OP);
  ints("logic_op_mode", GL_LOGIC_OP_MODE, 1);
  enabled("sample_alpha_to_coverage", GL_SAMPLE_ALPHA_TO_COVERAGE);
  enabled("sample_alpha_to_one", GL_SAMPLE_ALPHA_TO_ONE);
  enabled("sample_coverage", GL_SAMPLE_COVERAGE);
  floats("sample_coverage_value", GL_SAMPLE_COVERAGE_VALUE, 1);
  ints("sample_coverage_invert", GL_SAMPLE_COVERAGE_INVERT, 1);
  enabled("sample_mask", GL_SAMPLE_MASK);
  indexed("sample_mask_value", GL_SAMPLE_MASK_VALUE, 0, 1);
  enabled("sample_shading", GL_SAMPLE_SHADING);
  floats("min_sample_shading", GL_MIN_SAMPLE_SHADING_VALUE, 1);
  enabled("polygon_offset_fill", GL_POLYGON_OFFSET_FILL);
  enabled("polygon_offset_line", GL_POLYGON_OFFSET_LINE);
  enabled("polygon_offset_point", GL_POLYGON_OFFSET_POINT);
  floats("polygon_offset_factor", GL_POLYGON_OFFSET_FACTOR, 1);
  floats("polygon_offset_units", GL_POLYGON_OFFSET_UNITS, 1);
  enabled("primitive_restart_fixed_index", GL_PRIMITIVE_RESTART_FIXED_INDEX);
  ints("primitive_restart_index", GL_PRIMITIVE_RESTART_INDEX, 1);
  ints("provoking_vertex", GL_PROVOKING_VERTEX, 1);
  enabled("dither", GL_DITHER);
  enabled("line_smooth", GL_LINE_SMOOTH);
  enabled("polygon_smooth", GL_POLYGON_SMOOTH);
  enabled("program_point_size", GL_PROGRAM_POINT_SIZE);
  floats("point_size", GL_POINT_SIZE, 1);
  ints("point_sprite_coord_origin", GL_POINT_SPRITE_COORD_ORIGIN, 1);
  floats("line_width", GL_LINE_WIDTH, 1);
  for (GLuint i = 0; i < 8; ++i)
    s[indexedName("clip_distance", i)] = {glIsEnabled(GL_CLIP_DISTANCE0 + i)};
  for (GLuint i = 0; i < 4; ++i) {
    GLdouble range[2] = {};
    glGetDoublei_v(GL_DEPTH_RANGE, i, range);
    s[indexedName("depth_range", i)] = {static_cast<long long>(range[0] * 1e6),
                                        static_cast<long long>(range[1] * 1e6)};
  }
  ints("stencil_back_func", GL_STENCIL_BACK_FUNC, 1);
  ints("stencil_back_ref", GL_STENCIL_BACK_REF, 1);
  ints("stencil_back_fail", GL_STENCIL_BACK_FAIL, 1);
  ints("stencil_pass_depth_fail", GL_STENCIL_PASS_DEPTH_FAIL, 1);
  enabled("depth_test", GL_DEPTH_TEST);
  ints("depth_func", GL_DEPTH_FUNC, 1);
  ints("depth_mask", GL_DEPTH_WRITEMASK, 1);
  enabled("stencil_test", GL_STENCIL_TEST);
  ints("stencil_func", GL_STENCIL_FUNC, 1);
  ints("stencil_ref", GL_STENCIL_REF, 1);
  ints("stencil_value_mask", GL_STENCIL_VALUE_MASK, 1);
  ints("stencil_writemask", GL_STENCIL_WRITEMASK, 1);
  ints("stencil_fail", GL_STENCIL_FAIL, 1);
  ints("stencil_pass_depth_pass", GL_STENCIL_PASS_DEPTH_PASS, 1);
  enabled("cull_face", GL_CULL_FACE);
  ints("cull_face_mode", GL_CULL_FACE_MODE, 1);
  ints("front_face", GL_FRONT_FACE, 1);
  ints("polygon_mode", GL_POLYGON_MODE, 1);
  enabled("rasterizer_discard", GL_RASTERIZER_DISCARD);
  enabled("framebuffer_srgb", GL_FRAMEBUFFER_SRGB);
  enabled("clip_distance0", GL_CLIP_DISTANCE0);
  enabled("clip_distance3", GL_CLIP_DISTANCE3);
  enabled("depth_clamp", GL_DEPTH_CLAMP);
  enabled("multisample", GL_MULTISAMPLE);
  enabled("primitive_restart", GL_PRIMITIVE_RESTART);
  ints("clip_origin", GL_CLIP_ORIGIN, 1);
  ints("clip_depth_mode", GL_CLIP_DEPTH_MODE, 1);
  ints("program", GL_CURRENT_PROGRAM, 1);
  ints("program_pipeline", GL_PROGRAM_PIPELINE_BINDING, 1);
  ints("vertex_array", GL_VERTEX_ARRAY_BINDING, 1);
  ints("array_buffer", GL_ARRAY_BUFFER_BINDING, 1);
  ints("active_texture", GL_ACTIVE_TEXTURE, 1);
  GLint active = 0;
  glGetIntegerv(GL_ACTIVE_TEXTURE, &active);
  // Every target's binding on the plugin's units and the next ones (glBindTextureUnit(u, 0)
  // clears all of a unit's targets, not only the one a pass used).
  static constexpr struct {
    const char* name;
    GLenum binding;
  } kTargets[] = {{"texture_1d", GL_TEXTURE_BINDING_1D},
                  {"texture_1d_array", GL_TEXTURE_BINDING_1D_ARRAY},
                  {"texture_2d", GL_TEXTURE_BINDING_2D},
                  {"texture_2d_array", GL_TEXTURE_BINDING_2D_ARRAY},
                  {"texture_2d_multisample", GL_TEXTURE_BINDING_2D_MULTISAMPLE},
                  {"texture_2d_multisample_array", GL_TEXTURE_BINDING_2D_MULTISAMPLE_ARRAY},
                  {"texture_3d", GL_TEXTURE_BINDING_3D},
                  {"texture_cube", GL_TEXTURE_BINDING_CUBE_MAP},
                  {"texture_cube_array", GL_TEXTURE_BINDING_CUBE_MAP_ARRAY},
                  {"texture_rectangle", GL_TEXTURE_BINDING_RECTANGLE},
                  {"texture_buffer", GL_TEXTURE_BINDING_BUFFER}};
  for (GLuint unit = 0; unit < 16; ++unit) {
    glActiveTexture(GL_TEXTURE0 + unit);
    for (const auto& target : kTargets) {
      GLint bound = 0;
      glGetIntegerv(target.binding, &bound);
      s[indexedName(target.name, unit)] = {bound};
    }
    GLint sampler = 0;
    glGetIntegerv(GL_SAMPLER_BINDING, &sampler);
    s[indexedName("sampler", unit)] = {sampler};
  }
  glActiveTexture(static_cast<GLenum>(active));
  ints("uniform_buffer", GL_UNIFORM_BUFFER_BINDING, 1);
  ints("shader_storage_buffer", GL_SHADER_STORAGE_BUFFER_BINDING, 1);
  ints("query_buffer", GL_QUERY_BUFFER_BINDING, 1);
  ints("pixel_pack_buffer", GL_PIXEL_PACK_BUFFER_BINDING, 1);
  ints("pixel_unpack_buffer", GL_PIXEL_UNPACK_BUFFER_BINDING, 1);
  for (GLuint i = 0; i < 4; ++i) {
    indexed("ubo", GL_UNIFORM_BUFFER_BINDING, i, 1);
    indexed("ubo_start", GL_UNIFORM_BUFFER_START, i, 1);
    indexed("ubo_size", GL_UNIFORM_BUFFER_SIZE, i, 1);
    indexed("ssbo", GL_SHADER_STORAGE_BUFFER_BINDING, i, 1);
    indexed("ssbo_start", GL_SHADER_STORAGE_BUFFER_START, i, 1);
  }
  for (GLuint i = 0; i < 4; ++i) {
    indexed("image_texture", GL_IMAGE_BINDING_NAME, i, 1);
    indexed("image_access", GL_IMAGE_BINDING_ACCESS, i, 1);
    indexed("image_format", GL_IMAGE_BINDING_FORMAT, i, 1);
  }
  ints("pack_alignment", GL_PACK_ALIGNMENT, 1);
  ints("unpack_alignment", GL_UNPACK_ALIGNMENT, 1);
  ints("unpack_row_length", GL_UNPACK_ROW_LENGTH, 1);
  ints("pack_row_length", GL_PACK_ROW_LENGTH, 1);
  ints("unpack_skip_rows", GL_UNPACK_SKIP_ROWS, 1);
  ints("draw_buffer0", GL_DRAW_BUFFER0, 1);
  ints("read_buffer", GL_READ_BUFFER, 1);
  return s;
}

}  // namespace postfxtest
