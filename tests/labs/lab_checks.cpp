#include "lab_checks.hpp"

#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <cmath>
#include <sstream>

namespace numlab::test {

const std::vector<std::string>& row_named(const CsvRows& rows, const std::string& name) {
  for (const auto& row : rows) {
    if (row.at(0) == name) return row;
  }
  FAIL("no row " << name);
  return rows.at(0);
}

void check_ratio(const std::string& text, const std::string& before, double t, double other) {
  const double ratio = other / t;
  const double rounding = 2 * 0.0051;  // relative error of a ratio of two 3-digit numbers
  const std::string word = ratio >= 1.0 ? "faster" : "slower";
  const double shown = ratio >= 1.0 ? ratio : 1.0 / ratio;
  const std::size_t at = text.find(before + " ");
  INFO(before << " at " << fmt::format("{:.3f}", shown) << "x " << word << " from the printed times");
  REQUIRE(at != std::string::npos);
  const std::string rest = text.substr(at + before.size() + 1, 40);
  if (rest.starts_with("as fast as")) {
    CHECK(std::abs(shown - 1.0) <= 0.01 + shown * rounding);
    return;
  }
  std::istringstream sentence(rest);
  double printed = 0.0;
  std::string times, direction, than;
  sentence >> printed >> times >> direction >> than;
  CHECK(times == "x");
  CHECK(printed >= 1.0);
  if (shown - 1.0 > shown * rounding) CHECK(direction == word);
  else CHECK((direction == "faster" || direction == "slower"));
  CHECK(than == "than");
  CHECK(std::abs(printed - shown) <= shown * rounding + 0.005);
}

}  // namespace numlab::test
