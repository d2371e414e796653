# postfx_module(<name> [PUBLIC_HEADERS] SOURCES <files>...)
#
# What every library module of the project is: a static library with a postfx::<name> alias,
# position-independent code (a host may link it into a shared object), the project's warnings,
# and an install into the exported postfxTargets set (a static library's private dependencies
# are still needed at the host's link). Only a module marked PUBLIC_HEADERS installs its
# include/ tree, which holds nothing but include/postfx/...: the installed package's public API
# is the plugin (postfx/) and the optional ocean (postfx/water/). Internal modules (glkit,
# gbuffer) install their archives only. Links, shaders and extra include directories stay with
# the module.
function(postfx_module name)
  cmake_parse_arguments(ARG "PUBLIC_HEADERS" "" "SOURCES" ${ARGN})
  add_library(${name} STATIC ${ARG_SOURCES})
  add_library(postfx::${name} ALIAS ${name})
  target_include_directories(${name} PUBLIC $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>)
  if(ARG_PUBLIC_HEADERS)
    target_include_directories(${name} PUBLIC $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
    install(DIRECTORY include/postfx DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
  endif()
  set_target_properties(${name} PROPERTIES POSITION_INDEPENDENT_CODE ON)
  # Installed archives share a lib/ with every other package: libpostfx_water.a, not libwater.a.
  if(NOT name STREQUAL "postfx")
    set_target_properties(${name} PROPERTIES OUTPUT_NAME postfx_${name})
  endif()
  project_warnings(${name})
  install(TARGETS ${name} EXPORT postfxTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
endfunction()
