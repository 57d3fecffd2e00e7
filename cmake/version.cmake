# ew_version.h for the programs' --version: the project version and, when the source tree
# is a git checkout and git is installed, its commit (short hash, "-dirty" with local
# changes) read at configure time. No network; a tarball build says "unknown".
set(EW_GIT_COMMIT "unknown")
find_package(Git QUIET)
if(GIT_FOUND)
  execute_process(COMMAND ${GIT_EXECUTABLE} rev-parse --short=12 HEAD
    WORKING_DIRECTORY ${PROJECT_SOURCE_DIR} OUTPUT_VARIABLE commit
    OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE commitResult ERROR_QUIET)
  if(commitResult EQUAL 0 AND commit)
    set(EW_GIT_COMMIT "${commit}")
    execute_process(COMMAND ${GIT_EXECUTABLE} diff --quiet HEAD --
      WORKING_DIRECTORY ${PROJECT_SOURCE_DIR} RESULT_VARIABLE dirty ERROR_QUIET)
    if(dirty EQUAL 1)
      string(APPEND EW_GIT_COMMIT "-dirty")
    endif()
  endif()
endif()
set(EW_GENERATED_DIR ${PROJECT_BINARY_DIR}/generated)
configure_file(${PROJECT_SOURCE_DIR}/cmake/version.h.in ${EW_GENERATED_DIR}/ew_version.h @ONLY)
