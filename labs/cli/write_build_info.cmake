# cmake -DSOURCE_DIR=... -DOUTPUT=... -DVERSION=... [-DGIT_EXECUTABLE=...] -P write_build_info.cmake
#
# Writes OUTPUT, a C++ file defining numlab::cli::build_version() (VERSION, the project's version)
# and numlab::cli::build_commit(): the git commit SOURCE_DIR was checked out at (12 hex digits, then
# " with local changes" when tracked files differ from it), or "unknown" when there is no git or
# SOURCE_DIR is not the top of a git checkout (a source archive). Run at every build; the file is
# rewritten only when its text changes, so an unchanged commit recompiles nothing.

set(commit "unknown")
# --no-optional-locks: reading the commit never takes the index lock a concurrent git command needs.
if(NOT DEFINED GIT_EXECUTABLE)
  find_program(GIT_EXECUTABLE git)
endif()
if(GIT_EXECUTABLE AND EXISTS "${GIT_EXECUTABLE}")
  execute_process(COMMAND "${GIT_EXECUTABLE}" --no-optional-locks -C "${SOURCE_DIR}" rev-parse --show-toplevel
                  OUTPUT_VARIABLE top OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE failed ERROR_QUIET)
  if(NOT failed)
    file(REAL_PATH "${top}" top)
    file(REAL_PATH "${SOURCE_DIR}" source)
  endif()
  # Only SOURCE_DIR's own checkout: a numlab archive unpacked inside another repository has no commit.
  if(NOT failed AND top STREQUAL source)
    execute_process(COMMAND "${GIT_EXECUTABLE}" --no-optional-locks -C "${SOURCE_DIR}" rev-parse --short=12 HEAD
                    OUTPUT_VARIABLE head OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE failed ERROR_QUIET)
    if(NOT failed AND head MATCHES "^[0-9a-f]+$")
      set(commit "${head}")
      execute_process(COMMAND "${GIT_EXECUTABLE}" --no-optional-locks -C "${SOURCE_DIR}" diff --quiet HEAD --
                      RESULT_VARIABLE changed OUTPUT_QUIET ERROR_QUIET)
      if(changed EQUAL 1)
        string(APPEND commit " with local changes")
      endif()
    endif()
  endif()
endif()

set(text "// Written by labs/cli/write_build_info.cmake at build time: do not edit.
#include \"cli/build_info.hpp\"

namespace numlab::cli {
const char* build_version() { return \"${VERSION}\"; }
const char* build_commit() { return \"${commit}\"; }
}  // namespace numlab::cli
")
set(old "")
if(EXISTS "${OUTPUT}")
  file(READ "${OUTPUT}" old)
endif()
if(NOT old STREQUAL text)
  file(WRITE "${OUTPUT}" "${text}")
endif()
