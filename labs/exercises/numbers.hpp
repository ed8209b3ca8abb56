#pragma once
// Numbers a student can compare (docs/exercises.md, "Messages"): a mismatched value is shown with
// 17 significant digits, enough to tell any two doubles apart, beside numlab's value and the
// difference between them.

#include <string>

namespace numlab::exercises {

// 17 significant digits: "-43.351312345678901" (a double printed so that it reads back exactly).
std::string digits17(double value);

// "differs by 1.4e-05, 3.1e-07 relative": the absolute difference, and the relative one when
// `expected` is neither 0 nor non-finite ("differs by 0.5" alone then).
std::string difference(double yours, double expected);

// "YOURS, expected EXPECTED (differs by D, R relative)", each value with 17 digits.
std::string compared(double yours, double expected);

}  // namespace numlab::exercises
