// What the program says about itself: `numlab --version`, the exit codes in `numlab --help`, and
// the listings `numlab models` and `numlab labs` as tables that fit an 80-column terminal.

#include <catch2/catch.hpp>
#include <algorithm>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "run_numlab.hpp"

using numlab::test::run_numlab;
using Catch::Matchers::Contains;

namespace {

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// A listing's table: the header line, the rule under it, then rows and the lines their last
// column wraps onto, up to the first empty line or the first line that does not start with two
// spaces (the closing sentence).
struct Listing {
  std::string out;  // the whole output
  std::string header;
  std::vector<std::string> body;
};

Listing table_of(const std::string& out) {
  const std::vector<std::string> lines = lines_of(out);
  REQUIRE(lines.size() > 2);
  REQUIRE(lines[1].find_first_not_of(' ') == 2);
  REQUIRE(lines[1].find_first_not_of("- ") == std::string::npos);
  Listing listing{out, lines[0], {}};
  for (std::size_t i = 2; i < lines.size() && lines[i].starts_with("  "); ++i) listing.body.push_back(lines[i]);
  return listing;
}

// Every line of the output fits 80 columns.
void check_fits_80_columns(const std::string& out) {
  for (const std::string& line : lines_of(out)) {
    INFO(line);
    CHECK(line.size() <= 80);
  }
}

// The last column's text starts, on every line of the table, where its header starts: a row has
// at least two spaces before it, and a wrapped line has nothing else.
void check_last_column_aligned(const Listing& listing, const std::string& last_header) {
  const std::size_t column = listing.header.find(last_header);
  REQUIRE(column != std::string::npos);
  for (const std::string& line : listing.body) {
    INFO(line);
    REQUIRE(line.size() > column);
    CHECK(line[column] != ' ');
    CHECK(line.substr(column - 2, 2) == "  ");
  }
}

// A right-aligned column: on every row (a line that starts with a name), its cell ends where its
// header ends.
void check_right_aligned(const Listing& listing, const std::string& header) {
  const std::size_t end = listing.header.find(header) + header.size();
  for (const std::string& line : listing.body) {
    if (line[2] == ' ') continue;  // a wrapped line
    INFO(line);
    CHECK(line[end - 1] != ' ');
    CHECK(line[end] == ' ');
  }
}

// Runs `numlab COMMAND`, a listing: exit 0, every line within 80 columns, the last column (headed
// `last_header`) aligned on every line of the table.
Listing checked_listing(const std::string& command, const std::string& last_header) {
  const auto run = run_numlab(command);
  REQUIRE(run.exit_code == 0);
  INFO(run.out);
  check_fits_80_columns(run.out);
  const Listing listing = table_of(run.out);
  check_last_column_aligned(listing, last_header);
  return listing;
}

}  // namespace

TEST_CASE("numlab --version: the project's version and the git commit, exit 0", "[cli][version]") {
  const auto run = run_numlab("--version");
  CHECK(run.exit_code == 0);
  CHECK(run.err.empty());
  INFO(run.out);
  const std::regex expected("numlab " + std::regex_replace(std::string(NUMLAB_PROJECT_VERSION), std::regex("\\."), "\\.") +
                            " \\(git commit ([0-9a-f]{12}( with local changes)?|unknown)\\)\n");
  CHECK(std::regex_match(run.out, expected));
}

TEST_CASE("numlab --help lists the exit codes the program uses", "[cli][help]") {
  const auto run = run_numlab("--help");
  CHECK(run.exit_code == 0);
  CHECK_THAT(run.out, Contains("--version"));
  std::string footer = run.out.substr(run.out.find("Exit codes:"));
  std::replace(footer.begin(), footer.end(), '\n', ' ');
  CHECK_THAT(footer, Contains("0 success;") && Contains("1 the method ran but did not succeed") &&
                         Contains("a failed check") && Contains("2 bad usage or bad input"));
  // And they are the codes the program gives: 1 for a method that fails, 2 for bad input.
  CHECK(run_numlab("solve linear --method gepp-no-pivot --generate wilkinson:0").exit_code == 2);
  CHECK(run_numlab("mechanism mustang --crank 80").exit_code == 1);
}

TEST_CASE("numlab models: a table that fits 80 columns, its columns aligned", "[cli][models]") {
  const Listing listing = checked_listing("models", "title; blocks in order");
  INFO(listing.out);
  CHECK(listing.header.starts_with("  name "));
  for (const char* numbers : {"joints", "unknowns", "driver"}) check_right_aligned(listing, numbers);
  for (const char* model : {"chebyshev", "four-bar", "isosceles-slider-crank", "mustang", "stephenson-iii", "watt-i",
                            "inverted-slider-crank", "whitworth", "hydraulic-boom", "watt-straight-line", "five-bar"}) {
    CHECK_THAT(listing.out, Contains(std::string("\n  ") + model + " "));
  }
  // The title and the blocks of the widest row, wrapped but whole.
  std::string joined = listing.out;
  std::replace(joined.begin(), joined.end(), '\n', ' ');
  joined = std::regex_replace(joined, std::regex(" +"), " ");
  CHECK_THAT(joined, Contains("Isosceles slider-crank (branches cross at 90 and 270 degrees) explicit, dyad"));
  CHECK_THAT(joined, Contains("explicit, dyad, explicit, dyad, explicit, explicit, explicit, dyad, dyad, explicit"));
}

TEST_CASE("numlab labs: a table that fits 80 columns, the long names aligned with the short", "[cli][labs]") {
  const Listing listing = checked_listing("labs", "what it shows");
  INFO(listing.out);
  CHECK_THAT(listing.out, Contains("\n  jansen-sequential  Sequential vs full Newton"));
  CHECK_THAT(listing.out, Contains("\n  gauss              Gaussian elimination"));
}
