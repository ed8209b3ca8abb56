#include "exercises/numbers.hpp"

#include <cmath>
#include <fmt/format.h>

namespace numlab::exercises {

std::string digits17(double value) { return fmt::format("{:.17g}", value); }

std::string difference(double yours, double expected) {
  const double absolute = std::abs(yours - expected);
  std::string text = fmt::format("differs by {:.2g}", absolute);
  if (expected != 0.0 && std::isfinite(expected) && std::isfinite(absolute)) {
    text += fmt::format(", {:.2g} relative", absolute / std::abs(expected));
  }
  return text;
}

std::string compared(double yours, double expected) {
  return fmt::format("{}, expected {} ({})", digits17(yours), digits17(expected), difference(yours, expected));
}

}  // namespace numlab::exercises
