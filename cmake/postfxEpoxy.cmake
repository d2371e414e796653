# postfx::epoxy, the GL loader every module links. Found with plain find_path/find_library
# rather than pkg_check_modules because this file is also installed beside postfxConfig.cmake
# and runs in the host's project: it must not set EPOXY_* variables there, and must let a
# QUIET find_package(postfx) fail quietly. Its cache entries carry the POSTFX_ prefix.
if(NOT TARGET postfx::epoxy)
  find_path(POSTFX_EPOXY_INCLUDE_DIR epoxy/gl.h)
  find_library(POSTFX_EPOXY_LIBRARY NAMES epoxy)
  mark_as_advanced(POSTFX_EPOXY_INCLUDE_DIR POSTFX_EPOXY_LIBRARY)
  if(POSTFX_EPOXY_INCLUDE_DIR AND POSTFX_EPOXY_LIBRARY)
    add_library(postfx::epoxy UNKNOWN IMPORTED)
    set_target_properties(postfx::epoxy PROPERTIES
      IMPORTED_LOCATION "${POSTFX_EPOXY_LIBRARY}"
      INTERFACE_INCLUDE_DIRECTORIES "${POSTFX_EPOXY_INCLUDE_DIR}")
  endif()
endif()
