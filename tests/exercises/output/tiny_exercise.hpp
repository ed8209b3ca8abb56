#pragma once
// A tiny exercise made for the output tests: the student returns the sum of a list. Its checks
// compare with the sum computed here, so a correct program passes and the stubs fail.

#include <string>

#include "exercises/exercise.hpp"

namespace numlab::test {

exercises::Exercise tiny_exercise();

// A correct solve(request) body for each starter language (the stub replaced).
exercises::Stubs tiny_solutions();

}  // namespace numlab::test
