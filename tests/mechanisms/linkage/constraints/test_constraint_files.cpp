// The reader's new tables and keys (docs/linkage-files.md): what it reads from a slider on a link, an
// actuator and a motor, and each refusal at its FILE:LINE:COLUMN with its one-line problem.

#include <catch2/catch.hpp>

#include <string>

#include "description_text.hpp"
#include "numlab/mechanisms/linkage/linkage_description.hpp"

using namespace numlab::mechanisms;
using numlab::mechanisms::testing::check_refused;
using numlab::mechanisms::testing::lines;

namespace {

// Lines 1-18: an inverted slider-crank's joints and links, and a body B, D, E; the items under test
// start at line 19.
const std::string head = lines({
    "[linkage]",              // 1
    "name = \"t\"",           // 2
    "[ground]",               // 3
    "O = [0, 0]",             // 4
    "B = [3, 0]",             // 5
    "[joints]",               // 6
    "A = [0.5, 0.866]",       // 7
    "C = [-1.7, 1.6]",        // 8
    "D = [1, 1]",             // 9
    "E = [2, 2]",             // 10
    "[[link]]",               // 11
    "joints = [\"O\", \"A\"]",  // 12
    "length = 1",             // 13
    "[[link]]",               // 14
    "joints = [\"B\", \"C\"]",  // 15
    "length = 5",             // 16
    "[[body]]",               // 17
    "joints = [\"C\", \"D\", \"E\"]\nlocal = [[0, 0], [1, 0], [1, 1]]",  // 18, 19
});
// Line 20 on.
const std::string crank = lines({"[driver]", "type = \"crank\"", "pivot = \"O\"", "joint = \"A\"", "angle = 60"});

std::string slider(std::initializer_list<std::string> keys) { return head + lines({"[[slider]]"}) + lines(keys) + crank; }

}  // namespace

TEST_CASE("A slider on a link: read, and refused at its place", "[linkage-file][constraints][bad-input]") {
  const LinkageDescription d = parse_linkage_description(slider({"joint = \"A\"", "line = [\"B\", \"C\"]", "offset = 0.25"}), "t.toml");
  REQUIRE(d.sliders.size() == 1);
  CHECK(d.sliders[0].on_link());
  CHECK(d.sliders[0].line_from == d.joint_index("B"));
  CHECK(d.sliders[0].line_to == d.joint_index("C"));
  CHECK(d.sliders[0].offset == 0.25);
  // Two joints of one body carry a slot too.
  CHECK(parse_linkage_description(slider({"joint = \"A\"", "line = [\"D\", \"E\"]"}), "t.toml").sliders[0].on_link());
  check_refused(slider({"joint = \"A\"", "line = [\"B\", \"C\"]", "through = [0, 0]"}), 22, 8,
                "a [[slider]] runs on a fixed line (through = [x, y]) or on a moving link's line (line = [\"B\", \"C\"]): give one of the two");
  check_refused(slider({"joint = \"A\"", "line = [\"B\", \"D\"]"}), 22, 8,
                "the slider's line 'B' -> 'D' is not on one [[link]] or [[body]]: name two joints of the link that carries the slot");
  check_refused(slider({"joint = \"C\"", "line = [\"D\", \"C\"]"}), 22, 14, "the slider's joint 'C' cannot also define its line");
  check_refused(slider({"joint = \"A\"", "line = [\"B\", \"X\"]"}), 22, 14, "unknown joint 'X'");
  check_refused(slider({"joint = \"A\"", "line = [\"B\"]"}), 22, 8, "a slider's line must be two joint names, [\"B\", \"C\"]");
  check_refused(slider({"joint = \"A\"", "line = [\"B\", \"B\"]"}), 22, 8, "a slider's line needs two different joints");
  check_refused(slider({"joint = \"A\"", "line = [\"B\", \"C\"]", "angle = 10"}), 23, 9,
                "a slider on a link runs along its line B -> C: 'angle' goes with 'through' only");
  check_refused(slider({"joint = \"A\"", "through = [0, 0]", "offset = 1"}), 23, 10,
                "a slider's offset goes with line = [\"B\", \"C\"]; a fixed line is placed by 'through'");
  check_refused(slider({"joint = \"A\"", "line = [\"B\", \"C\"]", "offset = nan"}), 23, 10, "a slider's offset must be finite, got nan");
  // One slider per joint, whichever kind.
  check_refused(head + lines({"[[slider]]", "joint = \"A\"", "line = [\"B\", \"C\"]", "[[slider]]", "joint = \"A\"", "through = [0, 0]"}) +
                    crank,
                24, 9, "joint 'A' already has a slider at line 20");
  // A slider driver moves a joint along a fixed line; a slot's joint is driven by an actuator.
  check_refused(head + lines({"[[slider]]", "joint = \"A\"", "line = [\"B\", \"C\"]", "[driver]", "type = \"slider\"", "joint = \"A\"",
                              "travel = 1"}),
                25, 9, "joint 'A' slides on a moving link: drive the distance with type = \"actuator\" instead of a slider driver");
}

TEST_CASE("An actuator driver: read, and refused at its place", "[linkage-file][constraints][bad-input]") {
  const auto actuator = [](std::initializer_list<std::string> keys) { return head + lines({"[driver]", "type = \"actuator\""}) + lines(keys); };
  const LinkageDescription d = parse_linkage_description(actuator({"joints = [\"O\", \"C\"]", "length = 2.5"}), "t.toml");
  CHECK(d.driver.kind == DriverKind::actuator);
  CHECK(d.driver.from == d.joint_index("O"));
  CHECK(d.driver.joint == d.joint_index("C"));
  CHECK(d.driver.reference == 2.5);
  CHECK_FALSE(d.driver.angle());
  check_refused(actuator({"joints = [\"O\", \"A\"]", "length = 1"}), 22, 10,
                "an actuator between 'O' and 'A', which a [[link]] or [[body]] already holds at a fixed distance");
  check_refused(actuator({"joints = [\"D\", \"E\"]", "length = 1"}), 22, 10,
                "an actuator between 'D' and 'E', which a [[link]] or [[body]] already holds at a fixed distance");
  check_refused(actuator({"joints = [\"O\", \"B\"]", "length = 1"}), 22, 10, "an actuator between two ground joints cannot move anything");
  check_refused(actuator({"joints = [\"A\", \"A\"]", "length = 1"}), 22, 10, "an actuator from joint 'A' to itself");
  check_refused(actuator({"joints = [\"A\", \"Z\"]", "length = 1"}), 22, 16, "unknown joint 'Z'");
  check_refused(actuator({"joints = [\"A\"]", "length = 1"}), 22, 10, "an actuator's joints must be two joint names");
  check_refused(actuator({"joints = [\"O\", \"C\"]", "length = 0"}), 23, 10, "the actuator's length must be positive, got 0");
  check_refused(actuator({"joints = [\"O\", \"C\"]", "length = inf"}), 23, 10, "the actuator's length must be finite, got inf");
  check_refused(actuator({"joints = [\"O\", \"C\"]"}), 20, 1, "[driver] needs 'length'");
  check_refused(actuator({"joints = [\"O\", \"C\"]", "length = 1", "angle = 3"}), 24, 1, "unknown key 'angle' in an actuator [driver]");
}

TEST_CASE("A motor driver: read, and refused at its place", "[linkage-file][constraints][bad-input]") {
  const auto motor = [](std::initializer_list<std::string> keys) { return head + lines({"[driver]", "type = \"motor\""}) + lines(keys); };
  const LinkageDescription d =
      parse_linkage_description(motor({"pivot = \"C\"", "from = \"B\"", "joint = \"D\"", "angle = 40"}), "t.toml");
  CHECK(d.driver.kind == DriverKind::motor);
  CHECK(d.driver.pivot == d.joint_index("C"));
  CHECK(d.driver.from == d.joint_index("B"));
  CHECK(d.driver.joint == d.joint_index("D"));
  CHECK(d.driver.angle());
  // from and joint on one body: their angle is fixed.
  check_refused(motor({"pivot = \"C\"", "from = \"D\"", "joint = \"E\"", "angle = 40"}), 24, 9,
                "the motor's 'from' 'D' and 'joint' 'E' are on one link or body: a motor turns one link against another");
  check_refused(motor({"pivot = \"C\"", "from = \"B\"", "joint = \"B\"", "angle = 40"}), 24, 9,
                "the motor's 'from' 'B' and 'joint' 'B' are on one link or body: a motor turns one link against another");
  check_refused(motor({"pivot = \"C\"", "from = \"A\"", "joint = \"D\"", "angle = 40"}), 23, 8,
                "the motor's joint 'A' is on no [[link]] or [[body]] with pivot 'C'");
  check_refused(motor({"pivot = \"C\"", "from = \"C\"", "joint = \"D\"", "angle = 40"}), 23, 8,
                "the motor's pivot 'C' cannot also be its 'from' or 'joint'");
  check_refused(motor({"pivot = \"Y\"", "from = \"B\"", "joint = \"D\"", "angle = 40"}), 22, 9, "unknown joint 'Y'");
  check_refused(motor({"pivot = \"C\"", "from = \"B\"", "joint = \"D\"", "angle = nan"}), 25, 9, "the motor's angle must be finite, got nan");
  check_refused(motor({"pivot = \"C\"", "from = \"B\"", "joint = \"D\""}), 20, 1, "[driver] needs 'angle'");
  check_refused(motor({"pivot = \"C\"", "from = \"B\"", "joint = \"D\"", "angle = 4", "travel = 1"}), 26, 1,
                "unknown key 'travel' in a motor [driver]");
}
