// A link's `name` and the linkage's `output` (docs/linkage-files.md): read, defaulted, and refused
// with their place when invalid, repeated or unknown.

#include <catch2/catch.hpp>

#include <string>

#include "description_text.hpp"
#include "numlab/mechanisms/linkage/link_motion.hpp"
#include "numlab/mechanisms/linkage/linkage_description.hpp"

using namespace numlab::mechanisms;
using numlab::mechanisms::testing::check_refused;

namespace {

// A four-bar: line 3 is free for [linkage] keys, lines 12, 15 and 18 for the links' names.
std::string four_bar(const std::string& linkage_key, const std::string& crank_name, const std::string& coupler_name,
                     const std::string& rocker_name) {
  return "[linkage]\n"                                   // 1
         "name = \"t\"\n" +                              // 2
         linkage_key + "\n" +                            // 3
         "[ground]\nO = [0, 0]\nQ = [4, 0]\n"            // 4-6
         "[joints]\nA = [0.7, 0.7]\nB = [3, 2.5]\n"      // 7-9
         "[[link]]\njoints = [\"O\", \"A\"]\n" +         // 10-11
         crank_name + "\nlength = 1\n" +                 // 12-13
         "[[link]]\njoints = [\"A\", \"B\"]\n" +         // 14-15
         coupler_name + "\nlength = 3\n" +               // 16-17
         "[[link]]\njoints = [\"Q\", \"B\"]\n" +         // 18-19
         rocker_name + "\nlength = 2.5\n" +              // 20-21
         "[driver]\ntype = \"crank\"\npivot = \"O\"\njoint = \"A\"\nangle = 45\n";
}

}  // namespace

TEST_CASE("A link's name is its own or its joints joined by '-'; the output names a link, body or slider joint",
          "[linkage-file]") {
  const LinkageDescription d = parse_linkage_description(four_bar("output = \"rocker\"", "", "name = \"coupler\"", "name = \"rocker\""), "t.toml");
  const auto lines = link_lines(d);
  REQUIRE(lines.size() == 3);
  CHECK(lines[0].name == "O-A");
  CHECK(lines[1].name == "coupler");
  CHECK(lines[2].name == "rocker");
  CHECK(d.output == "rocker");
  CHECK(find_output(d, "rocker")->line == 2);
  CHECK_FALSE(find_output(d, "B"));  // a joint without a slider is not an output
}

TEST_CASE("Linkage files: link names and the output", "[linkage-file][bad-input]") {
  check_refused(four_bar("", "", "name = \"the coupler\"", ""), 16, 8,
                "invalid link name 'the coupler': use 1 to 32 letters, digits, '-' or '_'");
  check_refused(four_bar("", "", "name = 3", ""), 16, 8, "a link's name must be a string");
  check_refused(four_bar("", "name = \"bar\"", "name = \"bar\"", ""), 16, 8,
                "link name 'bar' is already the name of the link or body at line 12");
  check_refused(four_bar("", "", "name = \"O-A\"", ""), 16, 8,
                "link name 'O-A' is already the name of the link or body at line 10");
  check_refused(four_bar("output = \"B\"", "", "", ""), 3, 10, "unknown output 'B': name one of the links O-A, A-B, Q-B");
  check_refused(four_bar("output = 1", "", "", ""), 3, 10, "the linkage's output must be a string");
}
