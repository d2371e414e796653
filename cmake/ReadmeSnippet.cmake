# The README's integration snippet, compiled with every build: the ```cpp block after the
# marker "<!-- compiled: integration -->" is cut out of README.md at configure time and put in
# a function whose surroundings declare the host's own names (its textures, matrices, log()).
# An API change that breaks the README breaks the build. Re-configures when README.md changes.
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/README.md)
file(READ ${PROJECT_SOURCE_DIR}/README.md _readme)
string(FIND "${_readme}" "<!-- compiled: integration -->" _marker)
if(_marker EQUAL -1)
  message(FATAL_ERROR "README.md: the marker <!-- compiled: integration --> is missing")
endif()
string(SUBSTRING "${_readme}" ${_marker} -1 _tail)
string(FIND "${_tail}" "```cpp\n" _open)
string(FIND "${_tail}" "\n```\n" _close)
if(_open EQUAL -1 OR _close EQUAL -1 OR _close LESS _open)
  message(FATAL_ERROR "README.md: no ```cpp block after <!-- compiled: integration -->")
endif()
math(EXPR _start "${_open} + 7")
math(EXPR _length "${_close} - ${_start} + 1")
string(SUBSTRING "${_tail}" ${_start} ${_length} _snippet)
# The snippet's own #include goes to file scope; everything else is the body of a function.
string(REPLACE "#include <postfx/postfx.h>" "" _snippet "${_snippet}")
file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/readme_snippet.cpp.in
"// Generated from README.md by cmake/ReadmeSnippet.cmake: do not edit.
#include <epoxy/gl.h>
#include <glm/glm.hpp>
#include <postfx/postfx.h>
namespace readme_snippet {
// The host's names the snippet uses.
void log(const char* message);
extern GLuint gbufferDepth, gbufferNormal, gbufferAlbedo, hdrBuffer, oceanSlopes, sunShadowMap;
extern glm::dvec3 cameraWorldPosition, toSun;
extern glm::mat4 viewMatrix;
extern glm::dmat4 projection, sunWorldToClip;
extern glm::vec3 sunIrradiance;
extern double seaLevel;
void integrate() {
${_snippet}
}
}  // namespace readme_snippet
")
configure_file(${CMAKE_CURRENT_BINARY_DIR}/readme_snippet.cpp.in
               ${CMAKE_CURRENT_BINARY_DIR}/readme_snippet.cpp COPYONLY)
add_library(readme_snippet OBJECT ${CMAKE_CURRENT_BINARY_DIR}/readme_snippet.cpp)
target_link_libraries(readme_snippet PRIVATE postfx postfx::epoxy)
