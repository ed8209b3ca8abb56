#pragma once
// --speed: the crank's constant speed, a number and its unit, "120rpm" or "12.5rad/s" (one space
// between them allowed; the unit is required and spelled exactly so). In radians per second.

#include <cmath>
#include <stdexcept>
#include <string>
#include <string_view>

#include "numlab/printable_text.hpp"
#include "parsing/argument_parsing.hpp"

namespace numlab::cli {

inline double parse_speed(std::string_view text) {
  const std::string shown = "'" + printable(text.substr(0, 40)) + (text.size() > 40 ? "...'" : "'");
  const auto unit_of = [&](std::string_view unit) { return text.size() > unit.size() && text.ends_with(unit); };
  const std::string_view unit = unit_of("rpm") ? "rpm" : unit_of("rad/s") ? "rad/s" : "";
  if (unit.empty()) {
    throw std::invalid_argument("--speed " + shown + ": give the crank's speed with its unit, rpm or rad/s (e.g. 120rpm, 12.5rad/s)");
  }
  std::string_view number = text.substr(0, text.size() - unit.size());
  if (number.ends_with(' ')) number.remove_suffix(1);
  double value = 0.0;
  try {
    value = parse_finite_number(number);
  } catch (const std::invalid_argument& error) {
    throw std::invalid_argument("--speed " + shown + ": " + error.what());
  }
  if (value == 0.0) throw std::invalid_argument("--speed " + shown + ": a speed of zero moves nothing; give a nonzero speed");
  return unit == "rpm" ? value * 2.0 * 3.141592653589793238462643383279502884 / 60.0 : value;
}

}  // namespace numlab::cli
