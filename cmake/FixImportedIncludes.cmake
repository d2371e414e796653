# Debian's OpenImageIO package config lists /usr/include/opencv4 among its include directories
# although OpenCV is an optional dependency that is usually not installed; CMake then refuses
# to generate. Drop include directories that do not exist from an imported target.
function(drop_missing_include_dirs target)
  get_target_property(dirs ${target} INTERFACE_INCLUDE_DIRECTORIES)
  if(NOT dirs)
    return()
  endif()
  set(kept "")
  foreach(dir IN LISTS dirs)
    if(EXISTS "${dir}")
      list(APPEND kept "${dir}")
    endif()
  endforeach()
  set_target_properties(${target} PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${kept}")
endfunction()
