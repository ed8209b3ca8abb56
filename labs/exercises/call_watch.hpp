#pragma once
// numlab's watch on forbidden library calls (docs/exercises.md, "Library calls"). Before the
// student's program starts, numlab writes into a folder of its own:
// - python/sitecustomize.py and python/forbidden.txt: on PYTHONPATH, the first thing Python runs;
//   it wraps each forbidden function when its module is imported (the function still works) and
//   logs each call made from outside the library itself;
// - octave/init.m, octave/support/ and octave/wrappers/: Octave's site start-up file
//   (OCTAVE_SITE_INITFILE); it puts one wrapper per forbidden function first on the path, which
//   logs the call and runs the original (`A \ b` does not go through mldivide.m: not noticed).
// Both log to calls.log, one line per call (the function's name) and "+python" / "+octave" when
// the watch was loaded. C++ programs are not watched.

#include <cstdint>
#include <string>
#include <vector>

#include "exercises/forbidden_calls.hpp"
#include "exercises/library_calls.hpp"

namespace numlab::exercises {

// Writes the watch for `calls` into `folder` (made if need be) and returns the environment
// entries ("NAME=VALUE") that load it in a child. Nothing is written, and nothing returned, for a
// language whose list is empty. Throws std::system_error when a file cannot be written.
std::vector<std::string> install_call_watch(const std::string& folder, const ForbiddenCalls& calls);

// The log the watch installed in `folder` writes.
std::string call_log_path(const std::string& folder);

// The calls logged in `log` after byte `offset`, up to its last whole line (`offset` moves past
// it). A missing log is no calls.
LibraryCalls read_call_log(const std::string& log, std::uintmax_t& offset);

// The scripts (call_watch_scripts.cpp): the Python sitecustomize.py; Octave's start-up file for
// these functions, its helper numlab_watched_call.m, and the wrapper of one function.
const std::string& python_watch_script();
std::string octave_watch_init(const std::vector<std::string>& functions);
const std::string& octave_watch_helper();
std::string octave_watch_wrapper(const std::string& function);

}  // namespace numlab::exercises
