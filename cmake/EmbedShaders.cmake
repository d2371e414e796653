# embed_shaders(<target> NAMESPACE <ns> FILES <paths relative to shaders/>...)
#
# Generates a C++ source that defines `const glkit::ShaderLibrary& <ns>::shaderLibrary()`,
# holding every listed GLSL file as a string, keyed by its path relative to shaders/.
# #include "path" directives inside GLSL are resolved against the same set at run time, so a
# target embeds exactly the shaders (and shared headers) it needs and nothing else.
set(_EMBED_SHADERS_SCRIPT "${CMAKE_CURRENT_LIST_DIR}/embed_shaders_script.cmake")
set(POSTFX_SHADER_ROOT "${CMAKE_CURRENT_LIST_DIR}/../shaders" CACHE INTERNAL "")

function(embed_shaders target)
  cmake_parse_arguments(ARG "" "NAMESPACE" "FILES" ${ARGN})
  get_filename_component(root "${POSTFX_SHADER_ROOT}" ABSOLUTE)
  set(out "${CMAKE_CURRENT_BINARY_DIR}/${target}_embedded_shaders.cpp")
  set(deps "")
  foreach(f IN LISTS ARG_FILES)
    list(APPEND deps "${root}/${f}")
  endforeach()
  add_custom_command(OUTPUT "${out}"
    COMMAND ${CMAKE_COMMAND} -DROOT=${root} -DOUT=${out} -DNS=${ARG_NAMESPACE}
            "-DFILES=${ARG_FILES}" "-DOVERRIDE_DIR=${POSTFX_SHADER_DIR}"
            -P "${_EMBED_SHADERS_SCRIPT}"
    DEPENDS ${deps} "${_EMBED_SHADERS_SCRIPT}"
    COMMENT "Embedding GLSL for ${target}" VERBATIM)
  target_sources(${target} PRIVATE "${out}")
endfunction()
