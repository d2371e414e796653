// Compiled by both C++ and GLSL: the few macros that let one function body serve both.
// In C++ the GLSL vector types are GLM's and everything lives in namespace `shared`.
#ifndef POSTFX_SHARED_COMMON_H
#define POSTFX_SHARED_COMMON_H

#ifdef __cplusplus
#include <glm/glm.hpp>
#define SHARED_FN inline
#define SHARED_CONST inline constexpr
#define SHARED_BEGIN \
  namespace shared { \
  using namespace glm;
#define SHARED_END }
#else
#define SHARED_FN
#define SHARED_CONST const
#define SHARED_BEGIN
#define SHARED_END
#endif

#endif
