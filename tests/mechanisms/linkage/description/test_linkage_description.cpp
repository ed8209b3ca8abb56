// The reader of linkage description files (docs/linkage-files.md): valid files read field by field,
// and every kind of bad input refused with its exact place (line, column) and problem.

#include <catch2/catch.hpp>

#include <filesystem>
#include <initializer_list>
#include <string>

#include "description_text.hpp"
#include "numlab/mechanisms/linkage/linkage_description.hpp"

using namespace numlab::mechanisms;
using numlab::mechanisms::testing::check_refused;
using numlab::mechanisms::testing::error_of;
using numlab::mechanisms::testing::lines;
using Catch::Matchers::StartsWith;

namespace {

std::string fixture(const std::string& name) { return std::string(NUMLAB_LINKAGE_FILES) + "/" + name; }

// Lines 1 to 13 of most bad inputs below: a valid start, so that the line under test is line 14 on.
const std::string head = lines({
    "[linkage]",              // 1
    "name = \"t\"",           // 2
    "[ground]",               // 3
    "O = [0, 0]",             // 4
    "Q = [4, 0]",             // 5
    "[joints]",               // 6
    "A = [0.7, 0.7]",         // 7
    "B = [3, 2.5]",           // 8
    "P = [1.6, 2.3]",         // 9
    "S = [3.5, 0.5]",         // 10
    "[[link]]",               // 11
    "joints = [\"O\", \"A\"]",  // 12
    "length = 1",             // 13
});

const std::string crank = lines({"[driver]", "type = \"crank\"", "pivot = \"O\"", "joint = \"A\"", "angle = 45"});

// A problem with no single place: "t.toml: problem".
void check_refused_without_place(const std::string& text, const std::string& problem) {
  const LinkageFileError error = error_of(text);
  CHECK(error.problem() == problem);
  CHECK(error.place().line == 0);
  CHECK(std::string(error.what()) == "t.toml: " + problem);
}

}  // namespace

TEST_CASE("A full description is read field by field, in file order", "[linkage-file]") {
  const LinkageDescription d = read_linkage_description(fixture("four_bar_coupler_slider.toml"));
  CHECK(d.file == fixture("four_bar_coupler_slider.toml"));
  CHECK(d.name == "four-bar_slider");
  CHECK(d.title == "Crank-rocker with a coupler-driven slider");

  // Ground joints in file order (O before Q although toml++ sorts keys), then moving joints.
  REQUIRE(d.joints.size() == 6);
  const char* names[] = {"O", "Q", "A", "B", "P", "S"};
  const bool ground[] = {true, true, false, false, false, false};
  const double x[] = {0.0, 4.0, 0.7071, 3.1, 1.6, 3.5};
  const double y[] = {0.0, 0.0, 0.7071, 2.4, 2.3, 0.5};
  const int line[] = {8, 9, 12, 13, 14, 15};
  for (std::size_t i = 0; i < 6; ++i) {
    INFO("joint " << i);
    CHECK(d.joints[i].name == names[i]);
    CHECK(d.joints[i].ground == ground[i]);
    CHECK(d.joints[i].position.x() == x[i]);
    CHECK(d.joints[i].position.y() == y[i]);
    CHECK(d.joints[i].place.line == line[i]);
    CHECK(d.joints[i].place.column == 1);
    CHECK(d.joint_index(names[i]) == static_cast<int>(i));
  }
  CHECK(d.joint_index("Z") == -1);

  REQUIRE(d.links.size() == 3);
  CHECK((d.links[0].first == 0 && d.links[0].second == 2 && d.links[0].length == 1.0));
  CHECK((d.links[1].first == 1 && d.links[1].second == 3 && d.links[1].length == 2.5));
  CHECK((d.links[2].first == 4 && d.links[2].second == 5 && d.links[2].length == 2.5));
  CHECK(d.links[0].place.line == 17);
  CHECK(d.links[2].place.line == 29);

  REQUIRE(d.bodies.size() == 1);
  CHECK(d.bodies[0].name == "body 1");  // no name given: "body K", 1-based
  CHECK(d.bodies[0].joints == std::vector<int>{2, 3, 4});
  REQUIRE(d.bodies[0].local.size() == 3);
  CHECK(d.bodies[0].local[1] == Eigen::Vector2d(3.0, 0.0));
  CHECK(d.bodies[0].local[2] == Eigen::Vector2d(1.5, 1.0));
  CHECK(d.bodies[0].place.line == 25);

  REQUIRE(d.sliders.size() == 1);
  CHECK(d.sliders[0].joint == 5);
  CHECK(d.sliders[0].through == Eigen::Vector2d(0.0, 0.5));
  CHECK(d.sliders[0].angle_deg == 0.0);  // the default
  CHECK(d.sliders[0].place.line == 33);

  CHECK(d.driver.kind == DriverKind::crank);
  CHECK(d.driver.pivot == 0);
  CHECK(d.driver.joint == 2);
  CHECK(d.driver.slider == -1);
  CHECK(d.driver.reference == 45.0);
  CHECK(d.driver.place.line == 37);
}

TEST_CASE("A slider driver names its slider. A slider's angle and a body's name are read", "[linkage-file]") {
  const LinkageDescription d = read_linkage_description(fixture("offset_slider_crank.toml"));
  CHECK(d.name == "offset-slider-crank");
  CHECK(d.title.empty());
  REQUIRE(d.joints.size() == 3);
  CHECK(d.joints[1].name == "S");  // file order, not toml++'s sorted order (A before S)
  CHECK(d.joints[2].name == "A");
  REQUIRE(d.sliders.size() == 1);
  CHECK(d.sliders[0].through == Eigen::Vector2d(0.0, 0.25));
  CHECK(d.driver.kind == DriverKind::slider);
  CHECK(d.driver.joint == 1);
  CHECK(d.driver.slider == 0);
  CHECK(d.driver.pivot == -1);
  CHECK(d.driver.reference == 2.9);

  const LinkageDescription named = parse_linkage_description(
      head + lines({"[[body]]", "name = \"coupler\"", "joints = [\"A\", \"B\", \"P\"]",
                    "local = [[0, 0], [3, 0], [1.5, 1]]", "[[slider]]", "joint = \"S\"", "through = [0, 0.5]",
                    "angle = 30"}) + crank,
      "t.toml");
  CHECK(named.bodies.at(0).name == "coupler");
  CHECK(named.sliders.at(0).angle_deg == 30.0);
}

TEST_CASE("A crank may turn a joint that shares a body with its pivot", "[linkage-file]") {
  const std::string text = head + lines({"[[body]]", "joints = [\"O\", \"B\", \"P\"]", "local = [[0, 0], [3, 0], [1, 1]]",
                                         "[driver]", "type = \"crank\"", "pivot = \"O\"", "joint = \"P\"", "angle = 0"});
  CHECK(parse_linkage_description(text, "t.toml").driver.joint == 4);
}

TEST_CASE("Byte-order mark and CRLF line ends are read", "[linkage-file]") {
  std::string crlf;
  for (const char c : head + crank) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  CHECK(parse_linkage_description("\xEF\xBB\xBF" + crlf, "t.toml").joints.size() == 6);
}

TEST_CASE("Linkage files: TOML syntax errors give toml++'s place", "[linkage-file][bad-input]") {
  check_refused(lines({"[linkage]", "name = \"t\"", "[ground]", "O = [0, 0", "Q = [4, 0]"}), 5, 1,
                "TOML syntax error in array: expected comma or closing ']', saw 'Q'");
  const LinkageFileError error = error_of(lines({"[linkage]", "name = \"t\"", "[ground]", "O = [0, 0"}));
  CHECK(error.place().line == 4);
  CHECK_THAT(error.problem(), StartsWith("TOML syntax error in array: encountered end-of-file"));
  // A joint named twice in one table is a TOML error (a key redefined).
  const LinkageFileError twice = error_of(lines({"[linkage]", "name = \"t\"", "[ground]", "O = [0, 0]", "O = [1, 1]"}));
  CHECK(twice.place().line == 5);
  CHECK_THAT(twice.problem(), StartsWith("TOML syntax error in key-value pair: cannot redefine existing array 'O'"));
  // toml++ 3.3 asserted on these (fuzz_linkage_description found "[%"); now they are syntax errors.
  check_refused(lines({"[linkage]", "name = \"t\"", "[%"}), 3, 2,
                "TOML syntax error in key: expected bare key starting character or string delimiter, saw '%'");
  check_refused(lines({"[linkage]", "name = \"t\"", "[[[1]]]"}), 3, 3,
                "TOML syntax error in key: expected bare key starting character or string delimiter, saw '['");
  // toml++ 3.3 reached undefined behaviour on some non-ASCII characters (fuzz_linkage_description):
  // they are refused before it sees them, in a string too; escaped they are read.
  check_refused(lines({"[linkage]", "name = \"t\" \xC3\xA9"}), 2, 12,
                "the character U+00E9 is one toml++ 3.3 cannot read safely; in a string write it as \\u00E9");
  check_refused(lines({"# \xE3\x80\x81", "[linkage]"}), 1, 3,
                "the character U+3001 is one toml++ 3.3 cannot read safely; in a string write it as \\u3001");
  const std::string escaped = lines({"[linkage]", "name = \"t\"", "title = \"M\\u00E9canisme \xE2\x80\x94 \xE6\x9C\xBA\""});
  CHECK(parse_linkage_description(escaped + head.substr(head.find("[ground]")) + crank, "t.toml").title ==
        "M\xC3\xA9" "canisme \xE2\x80\x94 \xE6\x9C\xBA");
  // A byte-order mark before [linkage] still makes it a linkage with a syntax error.
  check_refused("\xEF\xBB\xBF[linkage]\nname = \"t\"\nO = [0, 0\n", 3, 11,
                "TOML syntax error in array: encountered end-of-file");
  // So is a second [driver].
  const LinkageFileError drivers = error_of(head + crank + lines({"[driver]"}));
  CHECK(drivers.place().line == 19);
  CHECK_THAT(drivers.problem(), StartsWith("TOML syntax error"));
}

namespace {

std::string repeated(const std::string& piece, int times) {
  std::string text;
  for (int k = 0; k < times; ++k) text += piece;
  return text;
}

const std::string too_deep = "keys, tables and arrays nested deeper than 64 levels";

}  // namespace

TEST_CASE("Linkage files: nesting deeper than 64 levels is refused before toml++ recurses into it",
          "[linkage-file][bad-input]") {
  const std::string start = lines({"# the root table: its keys are at level 1"});
  // 200,000 levels overflowed toml++'s stack; the 65th key part, header part or bracket is named.
  check_refused(start + "a" + repeated(".a", 199'999) + " = 1\n", 2, 129, too_deep);
  check_refused(start + "[a" + repeated(".a", 199'999) + "]\n", 2, 130, too_deep);
  check_refused(start + "[[a" + repeated(". \"a\"", 199'999) + "]]\n", 2, 321, too_deep);
  check_refused(start + "x = " + repeated("[", 200'000) + "\n", 2, 4 + 64, too_deep);
  check_refused(start + "x = " + repeated("{a = ", 200'000) + "\n", 2, 4 + 63 * 5 + 2, too_deep);
  check_refused(start + "x = [" + repeated("{a = [", 200'000) + "\n", 2, 5 + 31 * 6 + 2, too_deep);
  // Levels add up: a header's parts, a key's parts, arrays, inline tables in arrays.
  check_refused(start + "[t.u]\n" + "a" + repeated(".a", 62) + " = 1\n", 3, 125, too_deep);
  check_refused(start + "[t]\n" + "a" + repeated(".a", 61) + " = [[1]]\n", 3, 128, too_deep);
  // 64 levels reach toml++ (here: no [linkage] table); dots and brackets in strings, comments and
  // numbers count for nothing, nor do arrays already closed.
  CHECK(error_of(start + "a" + repeated(".a", 63) + " = 1\n").problem() != too_deep);
  CHECK(error_of(start + "x = " + repeated("[", 63) + repeated("]", 63) + "\n").problem() != too_deep);
  CHECK(error_of(start + "x = " + repeated("[[]", 100) + repeated("]", 100) + "\n").problem() == too_deep);
  CHECK(error_of(start + "x = " + repeated("[[], ", 100) + "[]" + repeated("]", 100) + "\n").problem() == too_deep);
  CHECK(error_of(start + "x = [" + repeated("[], ", 100) + "[]]\n").problem() != too_deep);
  const std::string busy = lines({"[linkage]", "name = \"t\"", "title = \"" + repeated("[a.", 60) + "\\\"\"",
                                  "# " + repeated("[a.", 100)}) +
                           head.substr(head.find("[ground]")) + crank +
                           lines({"", "[[link]]", "joints = ['B', '''P''']", "length = 1." + repeated("5", 70)});
  CHECK(parse_linkage_description(busy, "t.toml").links.size() == 2);
}

TEST_CASE("Linkage files: something that is not a linkage", "[linkage-file][bad-input]") {
  check_refused_without_place("", "not a linkage description: no [linkage] table");
  check_refused_without_place("# only a comment\n", "not a linkage description: no [linkage] table");
  check_refused_without_place("[package]\nname = \"x\"\n", "not a linkage description: no [linkage] table");
  // A NIST .dat file and binary bytes are not TOML either; the place is where TOML gave up.
  try {
    (void)read_linkage_description(std::string(NUMLAB_NIST_DIR) + "/Norris.dat");
    FAIL("Norris.dat accepted");
  } catch (const LinkageFileError& error) {
    CHECK(error.place().line == 1);
    CHECK_THAT(error.problem(), StartsWith("not a linkage description (no [linkage] table, and TOML syntax error"));
  }
  const LinkageFileError binary = error_of(std::string("\x7f" "ELF\x02\x01\x01\x00\x00\x00\xff\xfe\n", 13));
  CHECK(binary.place().line == 1);
  CHECK_THAT(binary.problem(), StartsWith("not a linkage description (no [linkage] table, and TOML syntax error"));
  CHECK(std::string(binary.what()).find('\x7f') == std::string::npos);  // bytes escaped, one line
  CHECK(std::string(binary.what()).find('\n') == std::string::npos);
}

TEST_CASE("Linkage files: the [linkage] table and its name", "[linkage-file][bad-input]") {
  check_refused(lines({"[linkage]", "title = \"x\""}), 1, 1, "[linkage] needs 'name'");
  check_refused(lines({"[linkage]", "name = \"four bar\""}), 2, 8,
                "invalid linkage name 'four bar': use 1 to 64 letters, digits, '-' or '_'");
  check_refused(lines({"[linkage]", "name = \"\""}), 2, 8, "invalid linkage name '': use 1 to 64 letters, digits, '-' or '_'");
  check_refused(lines({"[linkage]", "name = 3"}), 2, 8, "the linkage's name must be a string");
  check_refused(lines({"linkage = 3"}), 1, 1, "[linkage] must be a table");
  check_refused(lines({"[linkage]", "name = \"t\"", "title = \"a\\u001b[31m\""}), 3, 9,
                "title has a control character: 'a\\x1b[31m'");
}

TEST_CASE("Linkage files: unknown tables and keys name the key and its line", "[linkage-file][bad-input]") {
  check_refused(lines({"version = 2", "[linkage]", "name = \"t\""}), 1, 1, "unknown key 'version'");
  check_refused(head + lines({"[joint]", "C = [1, 1]"}) + crank, 14, 2, "unknown table [joint]");
  check_refused(head + lines({"[[links]]", "joints = [\"Q\", \"B\"]"}) + crank, 14, 3, "unknown table [[links]]");
  check_refused(lines({"[linkage]", "name = \"t\"", "author = \"me\""}), 3, 1, "unknown key 'author' in [linkage]");
  check_refused(head + lines({"[[link]]", "joints = [\"Q\", \"B\"]", "lenght = 2.5"}) + crank, 16, 1,
                "unknown key 'lenght' in [[link]]");
  check_refused(lines({"[linkage]", "name = \"t\"", "[link]", "joints = [\"Q\", \"B\"]"}), 3, 2,
                "write [[link]], one table per item");
  check_refused(lines({"driver = [1]", "[linkage]", "name = \"t\""}), 1, 1, "[driver] must be a table");
  check_refused(head + crank + lines({"travel = 1"}), 19, 1, "unknown key 'travel' in a crank [driver]");
}

TEST_CASE("Linkage files: joint names invalid, duplicate, unknown", "[linkage-file][bad-input]") {
  check_refused(lines({"[linkage]", "name = \"t\"", "[ground]", "\"O 1\" = [0, 0]"}), 4, 1,
                "invalid joint name 'O 1': use 1 to 32 letters, digits or '_'");
  check_refused(lines({"[linkage]", "name = \"t\"", "[joints]", "A-1 = [0, 0]"}), 4, 1,
                "invalid joint name 'A-1': use 1 to 32 letters, digits or '_'");
  const std::string long_name(33, 'J');
  check_refused(lines({"[linkage]", "name = \"t\"", "[joints]", long_name + " = [0, 0]"}), 4, 1,
                "invalid joint name '" + std::string(33, 'J').substr(0, 40) +
                    "': use 1 to 32 letters, digits or '_'");
  // 32 characters are allowed.
  const std::string longest(32, 'J');
  const std::string text = lines({"[linkage]", "name = \"t\"", "[ground]", "O = [0, 0]", "[joints]", longest + " = [1, 1]",
                                  "[[link]]", "joints = [\"O\", \"" + longest + "\"]", "length = 1", "[driver]",
                                  "type = \"crank\"", "pivot = \"O\"", "joint = \"" + longest + "\"", "angle = 45"});
  CHECK(parse_linkage_description(text, "t.toml").joints.back().name == longest);
  check_refused(lines({"[linkage]", "name = \"t\"", "[ground]", "O = [0, 0]", "[joints]", "O = [1, 1]"}), 6, 1,
                "joint 'O' is already defined at line 4");
  check_refused(head + lines({"[[link]]", "joints = [\"Q\", \"C\"]", "length = 2.5"}) + crank, 15, 16,
                "unknown joint 'C'");
  check_refused(head + lines({"[[link]]", "joints = [\"Q\", 7]", "length = 2.5"}) + crank, 15, 16,
                "a link's joint must be a string");
}

TEST_CASE("Linkage files: a position must be two finite numbers", "[linkage-file][bad-input]") {
  const auto joints = [](const std::string& a) {
    return lines({"[linkage]", "name = \"t\"", "[ground]", "O = [0, 0]", "[joints]", a});
  };
  check_refused(joints("A = [0.7]"), 6, 5, "the position of joint 'A' must be [x, y], two numbers");
  check_refused(joints("A = [0.7, 0.7, 0]"), 6, 5, "the position of joint 'A' must be [x, y], two numbers");
  check_refused(joints("A = 0.7"), 6, 5, "the position of joint 'A' must be [x, y], two numbers");
  check_refused(joints("A = [0.7, nan]"), 6, 11, "the position of joint 'A': y must be finite, got nan");
  check_refused(joints("A = [-inf, 1]"), 6, 6, "the position of joint 'A': x must be finite, got -inf");
  check_refused(joints("A = [0.7, \"1\"]"), 6, 11, "the position of joint 'A': y must be a number");
}

TEST_CASE("Linkage files: no moving joints", "[linkage-file][bad-input]") {
  check_refused(lines({"[linkage]", "name = \"t\"", "[ground]", "O = [0, 0]", "[joints]"}), 5, 1,
                "no moving joints: list them in [joints]");
  check_refused_without_place(lines({"[linkage]", "name = \"t\"", "[ground]", "O = [0, 0]"}),
                              "no moving joints: list them in [joints]");
}

TEST_CASE("Linkage files: more than 1000 joints", "[linkage-file][bad-input]") {
  std::string text = lines({"[linkage]", "name = \"t\"", "[ground]"});
  for (int k = 1; k <= 1001; ++k) {
    const std::string number = std::to_string(k);
    text.append("G").append(number).append(" = [").append(number).append(", 0]\n");
  }
  check_refused(text, 1004, 1, "more than 1000 joints");
}

TEST_CASE("Linkage files: links", "[linkage-file][bad-input]") {
  const auto link = [](const std::string& joints, const std::string& length) {
    return head + lines({"[[link]]", "joints = " + joints, "length = " + length}) + crank;
  };
  check_refused(link("[\"B\", \"B\"]", "1"), 15, 10, "a link from joint 'B' to itself");
  check_refused(link("[\"Q\", \"B\"]", "0"), 16, 10, "a link's length must be positive, got 0");
  check_refused(link("[\"Q\", \"B\"]", "-0.0"), 16, 10, "a link's length must be positive, got -0");
  check_refused(link("[\"Q\", \"B\"]", "-2.5"), 16, 10, "a link's length must be positive, got -2.5");
  check_refused(link("[\"Q\", \"B\"]", "inf"), 16, 10, "a link's length must be finite, got inf");
  check_refused(link("[\"Q\", \"B\"]", "nan"), 16, 10, "a link's length must be finite, got nan");
  check_refused(link("[\"Q\", \"B\"]", "\"2.5\""), 16, 10, "a link's length must be a number");
  check_refused(link("[\"Q\", \"B\", \"A\"]", "1"), 15, 10, "a link's joints must be two joint names");
  check_refused(link("[\"A\", \"O\"]", "1"), 15, 10, "a second link between 'A' and 'O' (the first is at line 11)");
  check_refused(head + lines({"[[link]]", "joints = [\"Q\", \"B\"]"}) + crank, 14, 1, "[[link]] needs 'length'");
  // The model squares lengths: a denormal one (or any below 1e-150) would square to zero, one above
  // 1e150 to infinity.
  check_refused(link("[\"Q\", \"B\"]", "5e-324"), 16, 10, "a link's length is 5e-324: lengths must be at least 1e-150 (their squares underflow)");
  check_refused(link("[\"Q\", \"B\"]", "1e151"), 16, 10, "a link's length is 1e+151: numbers must be at most 1e150 in size (their squares overflow)");
  CHECK(parse_linkage_description(link("[\"Q\", \"B\"]", "1e-150"), "t.toml").links.back().length == 1e-150);
}

TEST_CASE("Linkage files: bodies", "[linkage-file][bad-input]") {
  const auto body = [](const std::string& joints, const std::string& local) {
    return head + lines({"[[body]]", "joints = " + joints, "local = " + local}) + crank;
  };
  check_refused(body("[\"A\", \"B\"]", "[[0, 0], [3, 0]]"), 15, 10,
                "a body needs at least 3 joints, got 2 (two joints make a [[link]])");
  check_refused(body("[\"A\", \"B\", \"A\"]", "[[0, 0], [3, 0], [1, 1]]"), 15, 21, "joint 'A' appears twice in the body");
  check_refused(body("[\"A\", \"B\", \"C\"]", "[[0, 0], [3, 0], [1, 1]]"), 15, 21, "unknown joint 'C'");
  check_refused(body("[\"A\", \"B\", \"P\"]", "[[0, 0], [3, 0]]"), 16, 9,
                "'local' must give one [x, y] per joint: 3 joints, 2 points");
  check_refused(body("[\"A\", \"B\", \"P\"]", "[[0, 0], [3, 0], [1, inf]]"), 16, 30,
                "local point 3: y must be finite, got inf");
  check_refused(body("[\"A\", \"B\", \"P\"]", "[[0, 0], [3, 0], [3, 0]]"), 16, 9,
                "local points of joints 'B' and 'P' coincide in body 'body 1'");
  // Points on one line make a bar (a point on it or on its extension): accepted, marked collinear.
  CHECK(parse_linkage_description(body("[\"A\", \"B\", \"P\"]", "[[0, 0], [3, 0], [1.5, 0]]"), "t.toml").bodies[0].collinear);
  CHECK(parse_linkage_description(body("[\"A\", \"B\", \"P\"]", "[[0, 0], [3, 0], [4.5, 0]]"), "t.toml").bodies[0].collinear);
  CHECK_FALSE(parse_linkage_description(body("[\"A\", \"B\", \"P\"]", "[[0, 0], [3, 0], [1.5, 1]]"), "t.toml").bodies[0].collinear);
  check_refused(head + lines({"[[body]]", "name = \"the coupler\"", "joints = [\"A\", \"B\", \"P\"]",
                              "local = [[0, 0], [3, 0], [1.5, 1]]"}) + crank,
                15, 8, "invalid body name 'the coupler': use 1 to 32 letters, digits, '-' or '_'");
  check_refused(head + lines({"[[body]]", "local = [[0, 0], [3, 0], [1.5, 1]]"}) + crank, 14, 1, "[[body]] needs 'joints'");
}

TEST_CASE("Linkage files: a body's tolerances are relative to its size (1e-9 of its largest distance)",
          "[linkage-file][bad-input]") {
  const auto body = [](const std::string& local) {
    return head + lines({"[[body]]", "joints = [\"A\", \"B\", \"P\"]", "local = " + local}) + crank;
  };
  // 3e6 long, 1e-4 off the line: 3.3e-11 of its size, collinear (a bar).
  CHECK(parse_linkage_description(body("[[0, 0], [3e6, 0], [1.5e6, 1e-4]]"), "t.toml").bodies[0].collinear);
  // 3e-6 long, 3e-12 off the line: 1e-6 of its size, a (thin) triangle.
  CHECK_FALSE(parse_linkage_description(body("[[0, 0], [3e-6, 0], [1.5e-6, 3e-12]]"), "t.toml").bodies[0].collinear);
  // Two points 1e-3 apart in a body 3e6 long: 3.3e-10 of its size, coincident.
  check_refused(body("[[0, 0], [3e6, 0], [3e6, 1e-3]]"), 16, 9,
                "local points of joints 'B' and 'P' coincide in body 'body 1'");
}

TEST_CASE("Linkage files: sliders", "[linkage-file][bad-input]") {
  const auto slider = [](const std::string& joint, const std::string& through, const std::string& angle) {
    return head + lines({"[[slider]]", "joint = " + joint, "through = " + through, "angle = " + angle}) + crank;
  };
  check_refused(slider("\"C\"", "[0, 0.5]", "0"), 15, 9, "unknown joint 'C'");
  check_refused(slider("\"O\"", "[0, 0.5]", "0"), 15, 9, "a slider on ground joint 'O': it cannot move");
  check_refused(slider("\"S\"", "[0, inf]", "0"), 16, 15, "a slider's 'through' point: y must be finite, got inf");
  check_refused(slider("\"S\"", "[0, 0.5]", "nan"), 17, 9, "a slider's angle must be finite, got nan");
  check_refused(slider("\"S\"", "[0, 0.5]", "\"up\""), 17, 9, "a slider's angle must be a number");
  check_refused(head + lines({"[[slider]]", "joint = \"S\""}) + crank, 14, 1,
                "a [[slider]] runs on a fixed line (through = [x, y]) or on a moving link's line (line = [\"B\", \"C\"]): "
                "give one of the two");
  check_refused(head + lines({"[[slider]]", "joint = \"S\"", "through = [0, 0.5]", "[[slider]]", "joint = \"S\"",
                              "through = [0, 1]"}) + crank,
                18, 9, "joint 'S' already has a slider at line 14");
}

TEST_CASE("Linkage files: the driver", "[linkage-file][bad-input]") {
  check_refused_without_place(head, "no [driver] table: a linkage needs a driver ([driver]) or two ([[driver]] twice)");
  const auto driver = [](std::initializer_list<std::string> keys) { return head + lines({"[driver]"}) + lines(keys); };
  check_refused(driver({"type = \"rotor\""}), 15, 8,
                "unknown driver type 'rotor': use \"crank\", \"slider\", \"actuator\" or \"motor\"");
  check_refused(driver({"pivot = \"O\""}), 14, 1, "[driver] needs 'type'");
  check_refused(driver({"type = \"crank\"", "pivot = \"A\"", "joint = \"B\"", "angle = 0"}), 16, 9,
                "a driver on a joint that is not grounded: the crank's pivot 'A' is a moving joint");
  check_refused(driver({"type = \"crank\"", "pivot = \"C\"", "joint = \"A\"", "angle = 0"}), 16, 9, "unknown joint 'C'");
  check_refused(driver({"type = \"crank\"", "pivot = \"O\"", "joint = \"Q\"", "angle = 0"}), 17, 9,
                "the crank's joint 'Q' is a ground joint, not a moving one");
  check_refused(driver({"type = \"crank\"", "pivot = \"O\"", "joint = \"B\"", "angle = 0"}), 17, 9,
                "the crank's joint 'B' is on no [[link]] or [[body]] with pivot 'O'");
  check_refused(driver({"type = \"crank\"", "pivot = \"O\"", "joint = \"A\"", "angle = inf"}), 18, 9,
                "the crank's angle must be finite, got inf");
  check_refused(driver({"type = \"crank\"", "pivot = \"O\"", "joint = \"A\""}), 14, 1, "[driver] needs 'angle'");
  check_refused(driver({"type = \"slider\"", "joint = \"S\"", "travel = 1"}), 16, 9,
                "joint 'S' has no [[slider]] for the slider driver to move");
  const std::string slider = lines({"[[slider]]", "joint = \"S\"", "through = [0, 0.5]"});  // lines 14 to 16
  check_refused(head + slider + lines({"[driver]", "type = \"slider\"", "joint = \"S\"", "travel = nan"}), 20, 10,
                "the slider's travel must be finite, got nan");
  check_refused(head + slider + lines({"[driver]", "type = \"slider\"", "joint = \"S\"", "travel = 1", "pivot = \"O\""}),
                21, 1, "unknown key 'pivot' in a slider [driver]");
}

TEST_CASE("Linkage files: reading the file itself", "[linkage-file][bad-input]") {
  try {
    (void)read_linkage_description("/nonexistent/linkage.toml");
    FAIL("a missing file was read");
  } catch (const LinkageFileError& error) {
    CHECK(std::string(error.what()) == "/nonexistent/linkage.toml: cannot open the file (missing or unreadable)");
    CHECK(error.place().line == 0);
  }
  CHECK_THROWS_WITH(read_linkage_description(NUMLAB_LINKAGE_FILES), std::string(NUMLAB_LINKAGE_FILES) + ": is a directory, not a file");
}
