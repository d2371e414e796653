# postfx_module(<name> SOURCES <files>...)
#
# What every library module of the project is: a static library with a postfx::<name> alias,
# its include/ directory public (build tree and install), position-independent code (a host may
# link it into a shared object), the project's warnings, and an install into the exported
# postfxTargets set with its headers. Links, shaders and extra include directories stay with
# the module.
function(postfx_module name)
  cmake_parse_arguments(ARG "" "" "SOURCES" ${ARGN})
  add_library(${name} STATIC ${ARG_SOURCES})
  add_library(postfx::${name} ALIAS ${name})
  target_include_directories(${name} PUBLIC
    $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  set_target_properties(${name} PROPERTIES POSITION_INDEPENDENT_CODE ON)
  project_warnings(${name})
  install(TARGETS ${name} EXPORT postfxTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
  install(DIRECTORY include/${name} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
endfunction()
