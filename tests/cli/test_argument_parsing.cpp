// The command line's number, range and list arguments (labs/parsing/argument_parsing): valid text means
// what it always meant; bad text is refused with one line naming the option, the text and the part.

#include <catch2/catch.hpp>
#include <string>

#include "parsing/argument_parsing.hpp"

using namespace numlab::cli;
using Catch::Matchers::Contains;

TEST_CASE("One finite number (--crank)", "[cli-parsing]") {
  CHECK(parse_finite_number("+12.5") == 12.5);
  CHECK(parse_finite_number("-1e300") == -1e300);
  CHECK(finite_number_problem("90").empty());
  CHECK(finite_number_problem("1e400") == "'1e400' is out of range for a double");
  CHECK(finite_number_problem("nan") == "'nan' is not a finite number");
  CHECK(finite_number_problem("inf") == "'inf' is not a finite number");
  CHECK(finite_number_problem("12deg") == "'12deg' is not a finite number");
  CHECK(finite_number_problem("") == "no number given");
  CHECK(finite_number_problem("\x1b]0;x\x07") == "'\\x1b]0;x\\x07' is not a finite number");
}

TEST_CASE("Sweep ranges START:STOP:STEP keep their meaning", "[cli-parsing]") {
  const DegreeRange range = parse_degree_range("0:359:1", "--sweep");
  CHECK((range.start == 0.0 && range.stop == 359.0 && range.step == 1.0));
  const DegreeRange down = parse_degree_range("+10:-5.5:-0.5", "--sweep");
  CHECK((down.start == 10.0 && down.stop == -5.5 && down.step == -0.5));
  CHECK(parse_degree_range("0:99999:1", "--sweep").stop == 99999.0);  // 100000 poses: the cap
}

TEST_CASE("Sweep range refusals name the part and the problem", "[cli-parsing][bad-input]") {
  const auto sweep = [](const char* text) { return parse_degree_range(text, "--sweep"); };
  CHECK_THROWS_WITH(sweep("0:10"), "--sweep '0:10': expected START:STOP:STEP in degrees, e.g. 0:359:1");
  CHECK_THROWS_WITH(sweep("0:10:1:2"), Contains("expected START:STOP:STEP"));
  CHECK_THROWS_WITH(sweep("0::1"), "--sweep '0::1': STOP is empty");
  CHECK_THROWS_WITH(sweep("x:10:1"), "--sweep 'x:10:1': START 'x' is not a finite number");
  CHECK_THROWS_WITH(sweep("0:1e400:1"), "--sweep '0:1e400:1': STOP '1e400' is out of range for a double");
  CHECK_THROWS_WITH(sweep("0:10:inf"), Contains("STEP 'inf' is not a finite number"));
  CHECK_THROWS_WITH(sweep("0:10:1 "), Contains("STEP '1 ' is not a finite number"));
  CHECK_THROWS_WITH(sweep("0:10:0"), Contains("the step must be non-zero and point from START to STOP"));
  CHECK_THROWS_WITH(sweep("0:10:-1"), Contains("point from START to STOP"));
  CHECK_THROWS_WITH(sweep("1e20:1e20:1"), Contains("below the spacing of doubles"));
  CHECK_THROWS_WITH(sweep("0:100000:1"), "--sweep '0:100000:1': more than 100000 poses");
  CHECK_THROWS_WITH(sweep("-1e5:1e5:1"), Contains("more than 100000 poses"));
  // The whole text is shown escaped and cut at 40 bytes.
  const std::string long_text = "0:" + std::string(60, '9') + "x:1";
  CHECK_THROWS_WITH(sweep(long_text.c_str()), Contains("--sweep '0:" + std::string(38, '9') + "...': STOP '"));
}

TEST_CASE("Number lists for --x0", "[cli-parsing]") {
  CHECK(parse_number_list("1,-2.5,+3e2,.5", "--x0") == std::vector<double>{1.0, -2.5, 300.0, 0.5});
  CHECK(parse_number_list("7", "--x0") == std::vector<double>{7.0});
  CHECK_THROWS_WITH(parse_number_list("1,,2", "--x0"), "--x0 '1,,2': item 2 is empty");
  CHECK_THROWS_WITH(parse_number_list("1,2,", "--x0"), "--x0 '1,2,': item 3 is empty");
  CHECK_THROWS_WITH(parse_number_list("", "--x0"), "--x0 '': item 1 is empty");
  CHECK_THROWS_WITH(parse_number_list("1,abc", "--x0"), "--x0 '1,abc': item 2 'abc' is not a finite number");
  CHECK_THROWS_WITH(parse_number_list("1e400,1", "--x0"), Contains("item 1 '1e400' is out of range"));
  CHECK_THROWS_WITH(parse_number_list("1,nan", "--x0"), Contains("'nan' is not a finite number"));
  CHECK_THROWS_WITH(parse_number_list("1, 2", "--x0"), Contains("item 2 ' 2' is not a finite number"));
}

TEST_CASE("Generator specs KIND:N for --generate", "[cli-parsing]") {
  const std::vector<std::string> kinds = {"random", "hilbert", "gs-diverge"};
  const auto generate = [&](const char* text) { return parse_generator_spec(text, kinds, "gs-diverge", 4096, "--generate"); };
  CHECK(generate("random:8").kind == "random");
  CHECK(generate("random:8").size == 8);
  CHECK(generate("hilbert:4096").size == 4096);
  CHECK_FALSE(generate("gs-diverge").size);
  CHECK(generate("gs-diverge:5").size == 5);
  CHECK_THROWS_WITH(generate("random"), "--generate 'random': expected KIND:N, e.g. random:8");
  CHECK_THROWS_WITH(generate("banded:3"),
                    "--generate 'banded:3': unknown generator 'banded' (kinds: random, hilbert, gs-diverge)");
  CHECK_THROWS_WITH(generate(":3"), Contains("unknown generator ''"));
  CHECK_THROWS_WITH(generate("random:"), "--generate 'random:': size '' is not a whole number");
  CHECK_THROWS_WITH(generate("random:x"), Contains("size 'x' is not a whole number"));
  CHECK_THROWS_WITH(generate("random:8x"), Contains("size '8x' is not a whole number"));
  CHECK_THROWS_WITH(generate("random:+8"), Contains("size '+8' is not a whole number"));
  CHECK_THROWS_WITH(generate("random:4097"), "--generate 'random:4097': size '4097' is above the cap of 4096");
  CHECK_THROWS_WITH(generate("random:99999999999999999999"), Contains("is above the cap of 4096"));
  CHECK_THROWS_WITH(generate("random:0"), "--generate 'random:0': size 0 is below 1");
  CHECK_THROWS_WITH(generate("random:-99999999999999999999"), Contains("is below 1"));
}
