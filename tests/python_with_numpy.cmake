# Picks the Python 3 interpreter the tests run Python with: the first that can `import numpy`.
#
# Candidates, in order: Python3_EXECUTABLE if given (-DPython3_EXECUTABLE=...), `python3` on
# PATH, then Debian's /usr/bin/python3 (where `apt-get install python3-numpy` puts numpy). The
# first on PATH is often a version manager's shim (pyenv) whose Python lacks numpy, while .ci/setup
# installs numpy for Debian's; without this the tests would find the shim and fail to configure.
# Sets the cache variable Python3_EXECUTABLE and the imported target Python3::Interpreter, or
# stops with one line saying what is missing.

function(numlab_imports_numpy python result)
  execute_process(COMMAND ${python} -c "import numpy" RESULT_VARIABLE failed OUTPUT_QUIET ERROR_QUIET)
  if(failed)
    set(${result} FALSE PARENT_SCOPE)
  else()
    set(${result} TRUE PARENT_SCOPE)
  endif()
endfunction()

if(NOT Python3_EXECUTABLE)
  find_program(numlab_python_on_path NAMES python3 NO_CACHE)
  set(tried "")
  foreach(candidate IN ITEMS ${numlab_python_on_path} /usr/bin/python3)
    if(EXISTS "${candidate}" AND NOT Python3_EXECUTABLE)
      list(APPEND tried ${candidate})
      numlab_imports_numpy(${candidate} has_numpy)
      if(has_numpy)
        set(Python3_EXECUTABLE ${candidate} CACHE FILEPATH "Python 3 that imports numpy, for the tests")
      endif()
    endif()
  endforeach()
  if(NOT Python3_EXECUTABLE)
    list(JOIN tried ", " tried)
    message(FATAL_ERROR "no python3 that can import numpy (tried: ${tried}); the tests need python3-numpy")
  endif()
endif()

find_package(Python3 REQUIRED COMPONENTS Interpreter)
numlab_imports_numpy(${Python3_EXECUTABLE} has_numpy)
if(NOT has_numpy)
  message(FATAL_ERROR "${Python3_EXECUTABLE} cannot import numpy: the tests need python3-numpy")
endif()
message(STATUS "Tests run Python with ${Python3_EXECUTABLE} (imports numpy)")

# A test that needs one more module of that Python (scipy, say) calls this: configuration stops
# with one line naming the Debian package when the module is missing.
function(numlab_require_python_module module package)
  execute_process(COMMAND ${Python3_EXECUTABLE} -c "import ${module}" RESULT_VARIABLE failed OUTPUT_QUIET ERROR_QUIET)
  if(failed)
    message(FATAL_ERROR "${Python3_EXECUTABLE} cannot import ${module}: the tests need ${package} (bash .ci/setup installs it)")
  endif()
endfunction()
