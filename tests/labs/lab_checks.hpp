#pragma once
// Checks the lab tests share: a table's row by name, and a sentence's speed ratio against the
// times a table printed.

#include <string>
#include <vector>

#include "lab_output.hpp"

namespace numlab::test {

// The row of `rows` whose first cell is `name` (fails the test when there is none).
const std::vector<std::string>& row_named(const CsvRows& rows, const std::string& name);

// "2.07x faster than", "1.46x slower than" or "as fast as" (within 1%) right after `before` in
// `text`, for time t against time other, both as printed (3 significant digits, so each is off by at
// most 0.05/100 of itself): the sentence's ratio must be within what that rounding allows of the
// ratio of the printed times, plus its own last digit. Near 1 the rounding can flip the direction,
// so either word is then allowed.
void check_ratio(const std::string& text, const std::string& before, double t, double other);

}  // namespace numlab::test
