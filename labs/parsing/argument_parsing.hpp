#pragma once
// Number, range and list arguments of the command line (--crank, --sweep, --x0, --generate), each
// read whole: a bad one is refused with one line naming the option, what was given (quoted with
// numlab::printable, at most 40 bytes shown) and what is wrong with it. Nothing here reads a file
// or knows a sub-command, so the fuzzers (fuzz/) call these directly.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace numlab::cli {

// One finite number, the whole text (a leading '+' allowed). Throws std::invalid_argument saying
// what is wrong, e.g. "'1e400' is out of range" (the caller's option name goes in front).
double parse_finite_number(std::string_view text);

// The same check for a CLI11 validator: "" for a finite number, else the message above.
std::string finite_number_problem(std::string_view text);

// "START:STOP:STEP" in degrees: three finite numbers, the step non-zero and pointing from START to
// STOP, larger than the spacing of doubles there, and at most max_sweep_poses poses.
struct DegreeRange {
  double start, stop, step;
};
inline constexpr int max_sweep_poses = 100000;
DegreeRange parse_degree_range(std::string_view text, std::string_view option);

// "a,b,c": one or more finite numbers separated by commas, no empty item.
std::vector<double> parse_number_list(std::string_view text, std::string_view option);

// "KIND:N": KIND one of `kinds`, N a whole number from 1 to max_size; "KIND" alone only for
// `fixed_size_kind` (whose size is its own; `size` is then empty).
struct GeneratorSpec {
  std::string kind;
  std::optional<int> size;
};
GeneratorSpec parse_generator_spec(std::string_view text, const std::vector<std::string>& kinds,
                                   std::string_view fixed_size_kind, int max_size, std::string_view option);

}  // namespace numlab::cli
