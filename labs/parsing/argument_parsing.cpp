#include "parsing/argument_parsing.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <stdexcept>

#include "numlab/linalg/matrix_file.hpp"

namespace numlab::cli {

namespace {

using linalg::NumberTokenError;
using linalg::quoted_token;

// "'1e400' is out of range", or "" for a finite number (stored in `value`).
std::string number_problem(std::string_view text, double& value) {
  const NumberTokenError error = linalg::parse_number_token(text, value);
  switch (error) {
    case NumberTokenError::none: return "";
    case NumberTokenError::empty: return "is empty";
    case NumberTokenError::out_of_range: return quoted_token(text) + " is out of range for a double";
    case NumberTokenError::not_a_number:
    case NumberTokenError::not_finite: break;
  }
  return quoted_token(text) + " is not a finite number";
}

// "--sweep '0:x:1': " -- the start of every message about one argument.
std::string argument(std::string_view option, std::string_view text) {
  return std::string(option) + " " + quoted_token(text) + ": ";
}

}  // namespace

double parse_finite_number(std::string_view text) {
  double value = 0.0;
  const std::string problem = number_problem(text, value);
  if (!problem.empty()) throw std::invalid_argument(text.empty() ? "no number given" : problem);
  return value;
}

std::string finite_number_problem(std::string_view text) {
  try {
    parse_finite_number(text);
    return "";
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
}

DegreeRange parse_degree_range(std::string_view text, std::string_view option) {
  const std::string where = argument(option, text);
  // 1. Exactly two colons.
  const std::size_t first = text.find(':');
  const std::size_t second = first == std::string_view::npos ? first : text.find(':', first + 1);
  if (second == std::string_view::npos || text.find(':', second + 1) != std::string_view::npos) {
    throw std::invalid_argument(where + "expected START:STOP:STEP in degrees, e.g. 0:359:1");
  }
  // 2. Three finite numbers.
  const std::string_view parts[3] = {text.substr(0, first), text.substr(first + 1, second - first - 1),
                                     text.substr(second + 1)};
  const char* names[3] = {"START", "STOP", "STEP"};
  double values[3] = {};
  for (int i = 0; i < 3; ++i) {
    const std::string problem = number_problem(parts[i], values[i]);
    if (!problem.empty()) throw std::invalid_argument(where + names[i] + " " + problem);
  }
  const DegreeRange range{values[0], values[1], values[2]};
  // 3. A step that moves from START towards STOP, and is not lost in rounding there.
  if (range.step == 0.0 || (range.stop - range.start) * range.step < 0.0) {
    throw std::invalid_argument(where + "the step must be non-zero and point from START to STOP");
  }
  if (range.start + range.step == range.start || range.stop - range.step == range.stop) {
    throw std::invalid_argument(where + "the step is below the spacing of doubles at START or STOP");
  }
  // 4. At most max_sweep_poses poses (START, START + STEP, ... up to STOP).
  if (std::floor((range.stop - range.start) / range.step) >= max_sweep_poses) {
    throw std::invalid_argument(where + "more than " + std::to_string(max_sweep_poses) + " poses");
  }
  return range;
}

std::vector<double> parse_number_list(std::string_view text, std::string_view option) {
  std::vector<double> values;
  std::size_t begin = 0;
  while (begin <= text.size()) {
    const std::size_t end = std::min(text.find(',', begin), text.size());
    double value = 0.0;
    const std::string problem = number_problem(text.substr(begin, end - begin), value);
    if (!problem.empty()) {
      throw std::invalid_argument(argument(option, text) + "item " + std::to_string(values.size() + 1) + " " + problem);
    }
    values.push_back(value);
    begin = end + 1;
  }
  return values;
}

GeneratorSpec parse_generator_spec(std::string_view text, const std::vector<std::string>& kinds,
                                   std::string_view fixed_size_kind, int max_size, std::string_view option) {
  const std::string where = argument(option, text);
  // 1. A known kind.
  const std::size_t colon = text.find(':');
  const std::string_view kind = text.substr(0, colon);
  if (std::find(kinds.begin(), kinds.end(), kind) == kinds.end()) {
    std::string listed;
    for (const std::string& known : kinds) listed += (listed.empty() ? "" : ", ") + known;
    throw std::invalid_argument(where + "unknown generator " + quoted_token(kind) + " (kinds: " + listed + ")");
  }
  // 2. Its size, unless the kind has its own.
  if (colon == std::string_view::npos) {
    if (kind == fixed_size_kind) return {std::string(kind), std::nullopt};
    throw std::invalid_argument(where + "expected KIND:N, e.g. random:8");
  }
  const std::string_view size = text.substr(colon + 1);
  int n = 0;
  const auto [stop, error] = std::from_chars(size.data(), size.data() + size.size(), n);
  const bool digits_only = stop == size.data() + size.size();
  if (size.empty() || !digits_only || (error != std::errc() && error != std::errc::result_out_of_range)) {
    throw std::invalid_argument(where + "size " + quoted_token(size) + " is not a whole number");
  }
  if (error == std::errc::result_out_of_range && size.starts_with('-')) {
    throw std::invalid_argument(where + "size " + quoted_token(size) + " is below 1");
  }
  if (error == std::errc::result_out_of_range || n > max_size) {
    throw std::invalid_argument(where + "size " + quoted_token(size) + " is above the cap of " +
                                std::to_string(max_size));
  }
  if (n < 1) throw std::invalid_argument(where + "size " + std::to_string(n) + " is below 1");
  return {std::string(kind), n};
}

}  // namespace numlab::cli
