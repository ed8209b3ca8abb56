# cmake -D COMPILER=... -D FLAGS_FILE=... -D SOURCE=... -D EXPECT=compiles|refused [-D REFUSED=regex]
#   -P check_ownership.cmake
# Compiles SOURCE (syntax only) with the flags in FLAGS_FILE (one a line). EXPECT=compiles: it
# must compile cleanly as it is (the lvalue case: the positive control). EXPECT=refused: with
# NUMLAB_PASS_TEMPORARY it must fail, and for the right reason: GCC names a deleted function
# matching REFUSED, so a missing include or a typo cannot pass for a refusal.
file(STRINGS "${FLAGS_FILE}" flags)
set(arguments ${flags} -fsyntax-only "${SOURCE}")
if(EXPECT STREQUAL "refused")
  list(PREPEND arguments -DNUMLAB_PASS_TEMPORARY)
endif()
execute_process(COMMAND "${COMPILER}" ${arguments} RESULT_VARIABLE result ERROR_VARIABLE errors OUTPUT_VARIABLE output)
if(EXPECT STREQUAL "compiles")
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "${SOURCE} should compile with an lvalue, but does not:\n${output}${errors}")
  endif()
  message(STATUS "${SOURCE}: compiles with an lvalue")
elseif(EXPECT STREQUAL "refused")
  if(result EQUAL 0)
    message(FATAL_ERROR "${SOURCE} compiled with a temporary: a dangling reference is possible")
  endif()
  string(REGEX MATCHALL "use of deleted function[^\n]*" deleted "${errors}")
  list(FILTER deleted INCLUDE REGEX "${REFUSED}")
  list(LENGTH deleted count)
  if(count EQUAL 0)
    message(FATAL_ERROR "${SOURCE} failed to compile with a temporary, but not on a deleted constructor "
                        "matching '${REFUSED}':\n${errors}")
  endif()
  message(STATUS "${SOURCE}: a temporary is refused (${count} deleted constructor(s) named)")
else()
  message(FATAL_ERROR "EXPECT must be compiles or refused, not '${EXPECT}'")
endif()
