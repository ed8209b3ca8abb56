# cmake -DSOURCE_DIR=... -DWRITER=.../write_build_info.cmake -DWORK_DIR=... -P check_build_info.cmake
#
# What `numlab --version` reports as the commit, from labs/cli/write_build_info.cmake: git's HEAD
# for the source checkout, and "unknown" when git is missing or the folder is not the top of a git
# checkout (here a folder of the build tree, itself inside the checkout: a numlab archive unpacked
# inside another repository must not report that repository's commit).

function(commit_written source git result)
  set(output "${WORK_DIR}/build_info.cpp")
  file(REMOVE "${output}")
  set(git_argument "")
  if(git)
    set(git_argument "-DGIT_EXECUTABLE=${git}")
  endif()
  execute_process(COMMAND "${CMAKE_COMMAND}" "-DSOURCE_DIR=${source}" "-DOUTPUT=${output}" -DVERSION=9.8.7 ${git_argument}
                          -P "${WRITER}" RESULT_VARIABLE failed)
  if(failed)
    message(FATAL_ERROR "write_build_info.cmake failed (${failed}) for ${source}")
  endif()
  file(READ "${output}" text)
  if(NOT text MATCHES "build_version\\(\\) { return \"9.8.7\"; }")
    message(FATAL_ERROR "no version 9.8.7 in:\n${text}")
  endif()
  if(NOT text MATCHES "build_commit\\(\\) { return \"([^\"]*)\"; }")
    message(FATAL_ERROR "no commit in:\n${text}")
  endif()
  set(${result} "${CMAKE_MATCH_1}" PARENT_SCOPE)
endfunction()

file(MAKE_DIRECTORY "${WORK_DIR}/not-a-checkout")

commit_written("${SOURCE_DIR}" "${WORK_DIR}/no-such-git" commit)
if(NOT commit STREQUAL "unknown")
  message(FATAL_ERROR "without git the commit should be unknown, got '${commit}'")
endif()

commit_written("${WORK_DIR}/not-a-checkout" "" commit)
if(NOT commit STREQUAL "unknown")
  message(FATAL_ERROR "a folder that is not a checkout's top should give unknown, got '${commit}'")
endif()

find_program(git git)
if(git)
  execute_process(COMMAND "${git}" -C "${SOURCE_DIR}" rev-parse --short=12 HEAD OUTPUT_VARIABLE head
                  OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE not_a_checkout ERROR_QUIET)
  commit_written("${SOURCE_DIR}" "" commit)
  if(not_a_checkout AND NOT commit STREQUAL "unknown")
    message(FATAL_ERROR "the sources are not a git checkout: expected unknown, got '${commit}'")
  endif()
  if(NOT not_a_checkout AND NOT commit MATCHES "^${head}( with local changes)?$")
    message(FATAL_ERROR "expected git's HEAD ${head}, got '${commit}'")
  endif()
  message(STATUS "commit of the sources: ${commit}")
endif()
message(STATUS "without git, and outside a checkout: unknown")
