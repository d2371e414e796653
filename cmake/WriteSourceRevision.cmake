# Writes OUTPUT, a header defining OCEAN_SOURCE_REVISION as `git describe --always --dirty` of
# SOURCE_DIR ("unknown" outside a git checkout or without git), rewriting it only when the
# revision changed so that a build recompiles the one file that includes it only then.
# Run at build time (cmake -P), so a measurement names the code that was built, not the code that
# was configured.
set(revision "unknown")
find_program(GIT_EXECUTABLE git)
if(GIT_EXECUTABLE)
  execute_process(COMMAND ${GIT_EXECUTABLE} -C ${SOURCE_DIR} describe --always --dirty
    OUTPUT_VARIABLE described OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET RESULT_VARIABLE failed)
  if(NOT failed AND described)
    set(revision "${described}")
  endif()
endif()
set(content "#pragma once\n#define OCEAN_SOURCE_REVISION \"${revision}\"\n")
if(EXISTS ${OUTPUT})
  file(READ ${OUTPUT} previous)
endif()
if(NOT "${previous}" STREQUAL "${content}")
  file(WRITE ${OUTPUT} "${content}")
endif()
