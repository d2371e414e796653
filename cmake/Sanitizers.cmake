# Development only: POSTFX_SANITIZE builds every target with these sanitizers, e.g.
# "address,undefined" (clang: add float-cast-overflow, which -fsanitize=undefined leaves out).
# See docs/development.md (Sanitizers).
set(POSTFX_SANITIZE "" CACHE STRING "Comma-separated -fsanitize= list for every target (empty: none)")
if(POSTFX_SANITIZE)
  add_compile_options(-fsanitize=${POSTFX_SANITIZE} -fno-sanitize-recover=all
                      -fno-omit-frame-pointer -g)
  add_link_options(-fsanitize=${POSTFX_SANITIZE})
endif()

# postfx_sanitizer_runtime(<executable>): in sanitizer builds, the executable keeps every
# library loaded (a no-op dlclose): Mesa's driver does not free everything at exit, and
# LeakSanitizer can neither see that memory as reachable nor name the driver in lsan.supp once
# the driver is unmapped.
function(postfx_sanitizer_runtime target)
  if(POSTFX_SANITIZE)
    target_sources(${target} PRIVATE ${PROJECT_SOURCE_DIR}/cmake/sanitizers/keep_libraries_loaded.cpp)
  endif()
endfunction()

# The environment a test runs in under the sanitizers (empty otherwise).
set(POSTFX_SANITIZER_TEST_ENVIRONMENT "")
if(POSTFX_SANITIZE)
  set(POSTFX_SANITIZER_TEST_ENVIRONMENT
      "LSAN_OPTIONS=suppressions=${PROJECT_SOURCE_DIR}/cmake/sanitizers/lsan.supp:print_suppressions=0"
      "UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1")
endif()
