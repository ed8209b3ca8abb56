// The authoring checks (linkage_authoring_checks.hpp, docs/linkage-files.md "Authoring checks"):
// each warning and error on a small file, at the file's own size and scaled by 1e-8 and 1e7 (the
// verdicts must not depend on the unit), and no warning on any shipped model.
#include <catch2/catch.hpp>

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <regex>
#include <sstream>

#include "model_files.hpp"
#include "numlab/mechanisms/linkage/linkage_authoring_checks.hpp"

using namespace numlab::mechanisms;
using namespace numlab::mechanisms::testing;

namespace {

// Every number of a line that holds lengths or positions, times `factor` (angles, names and
// types stay).
std::string scaled(const std::string& text, double factor) {
  // A number not inside a name (P1): preceded by the line's start or by a character no name has.
  static const std::regex number(R"((^|[^A-Za-z_0-9.])(-?[0-9]+(\.[0-9]+)?(e-?[0-9]+)?))");
  std::istringstream in(text);
  std::string out, line;
  while (std::getline(in, line)) {
    const bool lengths = !line.starts_with("angle") && !line.starts_with("name") && !line.starts_with("title") &&
                         !line.starts_with("#") && !line.starts_with("[");
    if (lengths) {
      std::string changed;
      auto begin = std::sregex_iterator(line.begin(), line.end(), number);
      std::size_t last = 0;
      for (auto it = begin; it != std::sregex_iterator(); ++it) {
        const auto start = static_cast<std::size_t>(it->position(2));
        changed += line.substr(last, start - last);
        changed += fmt::format("{:.17g}", std::stod(it->str(2)) * factor);
        last = start + static_cast<std::size_t>(it->length(2));
      }
      line = changed + line.substr(last);
    }
    out += line + '\n';
  }
  return out;
}

// The shipped four-bar (crank 1.5 at 60 deg, coupler 4, rocker 3.5, ground 4.5). Lines: A 7, B 8,
// the links 9, 12, 15, angle 22.
std::string four_bar(const std::string& coupler_length = "4.0", const std::string& angle = "60.0") {
  return "[linkage]\nname = \"t\"\n[ground]\nO = [0.0, 0.0]\nQ = [4.5, 0.0]\n[joints]\nA = [0.75, 1.3]\nB = [4.0, 3.5]\n"
         "[[link]]\njoints = [\"O\", \"A\"]\nlength = 1.5\n"
         "[[link]]\njoints = [\"A\", \"B\"]\nlength = " + coupler_length + "\n"
         "[[link]]\njoints = [\"Q\", \"B\"]\nlength = 3.5\n"
         "[driver]\ntype = \"crank\"\npivot = \"O\"\njoint = \"A\"\nangle = " + angle + "\n";
}

// The four-bar with its coupler a body A, B, P (P at (2, 1.5) in the body, solved at (1.61, 3.65)).
// Lines: P 9, the links 10, 13, the body 16, angle 24, `extra` from 25.
std::string coupler_body(const std::string& p_rough = "[1.6, 3.65]", const std::string& p_local = "[2.0, 1.5]",
                         const std::string& extra = "") {
  return "[linkage]\nname = \"t\"\n[ground]\nO = [0.0, 0.0]\nQ = [4.5, 0.0]\n[joints]\nA = [0.75, 1.3]\nB = [4.0, 3.5]\n"
         "P = " + p_rough + "\n"
         "[[link]]\njoints = [\"O\", \"A\"]\nlength = 1.5\n"
         "[[link]]\njoints = [\"Q\", \"B\"]\nlength = 3.5\n"
         "[[body]]\nname = \"coupler\"\njoints = [\"A\", \"B\", \"P\"]\nlocal = [[0.0, 0.0], [4.0, 0.0], " + p_local + "]\n"
         "[driver]\ntype = \"crank\"\npivot = \"O\"\njoint = \"A\"\nangle = 60.0\n" + extra;
}

// The four-bar of four_bar() with the coupler point P of coupler_body() held by links A-P and B-P
// (2.5 each), then a body A, B, P with P at `p_local` (the triangle the links already make). Lines:
// P 9, the links 10, 13, 16, 24, 27, the body 30.
std::string links_then_body(const std::string& p_local) {
  std::string text = four_bar();
  text.insert(text.find("[[link]]"), "P = [1.6, 3.65]\n");
  return text + "[[link]]\njoints = [\"A\", \"P\"]\nlength = 2.5\n[[link]]\njoints = [\"B\", \"P\"]\nlength = 2.5\n"
                "[[body]]\nname = \"coupler\"\njoints = [\"A\", \"B\", \"P\"]\nlocal = [[0.0, 0.0], [4.0, 0.0], " + p_local + "]\n";
}

// coupler_body() and a second body over the same joints (in another order) at line 25.
std::string two_bodies(const std::string& local) {
  return coupler_body("[1.6, 3.65]", "[2.0, 1.5]",
                      "[[body]]\nname = \"copy\"\njoints = [\"B\", \"P\", \"A\"]\nlocal = " + local + "\n");
}

// The error `text`'s model gives: at `line`, starting with `start` and holding `also` (when not empty).
void check_model_error(const std::string& text, int line, const std::string& start, const std::string& also = "") {
  try {
    const LinkageModel model(parse_linkage_description(text, "t.toml"));
    FAIL("the description was accepted");
  } catch (const LinkageFileError& e) {
    CHECK(e.problem().starts_with(start));
    if (!also.empty()) CHECK(e.problem().find(also) != std::string::npos);
    CHECK(e.place().line == line);
  }
}

// A slider-crank whose slider runs at 30 deg through the pivot (S solved at (2.92, 1.686)). Lines:
// the slider 14, its angle 17.
std::string inclined_slider(const std::string& slider_angle) {
  return "[linkage]\nname = \"t\"\n[ground]\nO = [0.0, 0.0]\n[joints]\nA = [0.0, 1.0]\nS = [2.92, 1.69]\n"
         "[[link]]\njoints = [\"O\", \"A\"]\nlength = 1.0\n"
         "[[link]]\njoints = [\"A\", \"S\"]\nlength = 3.0\n"
         "[[slider]]\njoint = \"S\"\nthrough = [0.0, 0.0]\nangle = " + slider_angle + "\n"
         "[driver]\ntype = \"crank\"\npivot = \"O\"\njoint = \"A\"\nangle = 90.0\n";
}

std::vector<AuthoringWarning> warnings_of(const std::string& text) {
  const LinkageModel model(parse_linkage_description(text, "t.toml"));
  check_driver_angles(model.description());
  return authoring_warnings(model, polished_reference(model, {}));
}

const double scales[] = {1.0, 1e-8, 1e7};

}  // namespace

TEST_CASE("Authoring checks: a file that agrees with itself gives no warning, at any scale", "[linkage-authoring]") {
  for (double scale : scales) {
    INFO("scale " << scale);
    CHECK(warnings_of(scaled(four_bar(), scale)).empty());
    CHECK(warnings_of(scaled(coupler_body(), scale)).empty());
    CHECK(warnings_of(scaled(inclined_slider("30.0"), scale)).empty());
  }
}

TEST_CASE("Authoring checks: a link length that disagrees with the rough positions is named with both numbers",
          "[linkage-authoring]") {
  for (double scale : scales) {
    INFO("scale " << scale);
    const auto warnings = warnings_of(scaled(four_bar("3.0"), scale));
    REQUIRE(warnings.size() == 2);
    CHECK(warnings[0].place.line == 8);  // B, solved at (3.07, 3.20)
    CHECK(warnings[0].text.starts_with(fmt::format("joint B is solved {:.3g} from its rough position", 0.97464 * scale)));
    CHECK(warnings[1].place.line == 12);
    CHECK(warnings[1].text == fmt::format("link A-B: length {:g}, but its joints' rough positions are {:.4g} apart (31% longer)",
                                          3.0 * scale, 3.925 * scale));
    CHECK(warning_line("t.toml", warnings[1]).starts_with("t.toml:12: link A-B: length"));
  }
}

TEST_CASE("Authoring checks: a joint solved far from its rough position is named with the distance", "[linkage-authoring]") {
  for (double scale : scales) {
    INFO("scale " << scale);
    const auto warnings = warnings_of(scaled(coupler_body("[1.0, 3.0]"), scale));
    REQUIRE(warnings.size() == 1);
    CHECK(warnings[0].place.line == 9);
    CHECK(warnings[0].text.starts_with(fmt::format("joint P is solved {:.3g} from its rough position", 0.88899 * scale)));
    CHECK(warnings[0].text.ends_with(fmt::format("(more than a tenth of its shortest link, {:.3g})", 2.5 * scale)));
  }
}

TEST_CASE("Authoring checks: a body whose local coordinates are mirrored is a warning", "[linkage-authoring]") {
  for (double scale : scales) {
    INFO("scale " << scale);
    const auto warnings = warnings_of(scaled(coupler_body("[1.6, 3.65]", "[2.0, -1.5]"), scale));
    REQUIRE(warnings.size() == 2);
    CHECK(warnings[0].place.line == 9);  // P, solved on the other side of A-B
    CHECK(warnings[0].text.starts_with("joint P is solved"));
    CHECK(warnings[1].place.line == 16);
    CHECK(warnings[1].text ==
          "body 'coupler': its local coordinates are the mirror image of its joints' rough positions (A, B, P turn "
          "clockwise in 'local', counter-clockwise in [joints]); the body keeps its local shape");
  }
}

TEST_CASE("Authoring checks: a crank angle that disagrees with the rough positions is an error", "[linkage-authoring]") {
  for (double scale : scales) {
    INFO("scale " << scale);
    try {
      warnings_of(scaled(four_bar("4.0", "1.0472"), scale));
      FAIL("a crank angle in radians was accepted");
    } catch (const LinkageFileError& e) {
      CHECK(e.problem() == "the crank's angle = 1.0472 disagrees with the rough positions, which put O -> A at 60.0°; "
                           "angle = 1.0472 looks like radians: 60.0°, write angle = 60.0");
      CHECK(e.place().line == 22);
      CHECK(e.place().column == 9);
    }
    try {
      warnings_of(scaled(four_bar("4.0", "120.0"), scale));
      FAIL("a crank angle 60 deg off was accepted");
    } catch (const LinkageFileError& e) {
      CHECK(e.problem() == "the crank's angle = 120 disagrees with the rough positions, which put O -> A at 60.0° "
                           "(60.0° apart, more than 5°): fix the angle or A's rough position");
    }
    CHECK_NOTHROW(warnings_of(scaled(four_bar("4.0", "64.0"), scale)));  // within 5 deg: the rough place is rough
  }
}

TEST_CASE("Authoring checks: a slider angle that disagrees with its joint's rough position is an error",
          "[linkage-authoring]") {
  for (double scale : scales) {
    INFO("scale " << scale);
    try {
      warnings_of(scaled(inclined_slider("0.5236"), scale));
      FAIL("a slider angle in radians was accepted");
    } catch (const LinkageFileError& e) {
      CHECK(e.problem() == "slider S's angle = 0.5236 disagrees with the rough position of S, which puts its line at "
                           "30.1°; angle = 0.5236 looks like radians: 30.0°, write angle = 30.0");
      CHECK(e.place().line == 17);
    }
    try {
      warnings_of(scaled(inclined_slider("45.0"), scale));
      FAIL("a slider angle 15 deg off was accepted");
    } catch (const LinkageFileError& e) {
      CHECK(e.problem().starts_with("slider S's angle = 45 disagrees with the rough position of S, which puts its line "
                                    "at 30.1° (S is "));
    }
  }
}

TEST_CASE("Authoring checks: a redundant item is named at its own line, not by its joints", "[linkage-authoring]") {
  for (double scale : scales) {
    INFO("scale " << scale);
    const std::string text = scaled(coupler_body("[1.6, 3.65]", "[2.0, 1.5]", "[[link]]\njoints = [\"A\", \"B\"]\nlength = 4.0\n"), scale);
    try {
      const LinkageModel model(parse_linkage_description(text, "t.toml"));
      FAIL("a redundant link was accepted");
    } catch (const LinkageFileError& e) {
      CHECK(e.problem().starts_with("link A-B is redundant: with it, joints A, B"));
      // Measured, not assumed: the body holds A and B at the link's own length.
      CHECK(e.problem().find(fmt::format("the other items already hold its joints {:.6g} apart, its own length", 4.0 * scale)) !=
            std::string::npos);
      CHECK(e.place().line == 25);
    }
    // The same link a little longer than the body makes it: not redundant, contradictory.
    const std::string longer = scaled(coupler_body("[1.6, 3.65]", "[2.0, 1.5]", "[[link]]\njoints = [\"A\", \"B\"]\nlength = 4.2\n"), scale);
    try {
      const LinkageModel model(parse_linkage_description(longer, "t.toml"));
      FAIL("a contradictory link was accepted");
    } catch (const LinkageFileError& e) {
      CHECK(e.problem().starts_with("link A-B contradicts the other items: with it, joints A, B"));
      CHECK(e.problem().find(fmt::format("without it they hold its joints {:.6g} apart, it asks for {:.6g}", 4.0 * scale,
                                         4.2 * scale)) != std::string::npos);
      CHECK(e.place().line == 25);
    }
  }
}

TEST_CASE("Authoring checks: a redundant body is measured against the pose the other items give", "[linkage-authoring]") {
  const std::string with = "with it, joints A, B, P have 9 equations for 6 unknowns; ";
  for (double scale : scales) {
    INFO("scale " << scale);
    // The links A-B, A-P, B-P already make the body's triangle, in its shape: the body is named.
    check_model_error(scaled(links_then_body("[2.0, 1.5]"), scale), 30,
                      fmt::format("body coupler is redundant: {}the other items already hold its joints in its local "
                                  "shape (all 3 distances; A and B {:.6g} apart)",
                                  with, 4.0 * scale));
    // A body repeating another in a rotated and shifted frame, joints in another order: the same.
    check_model_error(scaled(two_bodies("[[1.0, 4.0], [-0.5, 2.0], [1.0, 0.0]]"), scale), 25,
                      fmt::format("body copy is redundant: {}the other items already hold its joints in its local "
                                  "shape (all 3 distances; B and A {:.6g} apart)",
                                  with, 4.0 * scale));
  }
}

TEST_CASE("Authoring checks: a redundant body that disagrees contradicts the others: the pair and both distances, or "
          "its mirror image",
          "[linkage-authoring]") {
  for (double scale : scales) {
    INFO("scale " << scale);
    // P at (2.3, 1.5): A-P 2.74591 (the links hold 2.5), B-P 2.26716; A-P is further off.
    check_model_error(scaled(links_then_body("[2.3, 1.5]"), scale), 30,
                      "body coupler contradicts the other items: with it, joints A, B, P",
                      fmt::format("; without it they hold joints A and P {:.6g} apart, its local coordinates ask for "
                                  "{:.6g};",
                                  2.5 * scale, std::sqrt(7.54) * scale));
    // The copy with P 0.4 further from A-B: B-P and P-A are equally off (either may be named).
    check_model_error(scaled(two_bodies("[[4.0, 0.0], [2.0, 1.9], [0.0, 0.0]]"), scale), 25,
                      "body copy contradicts the other items",
                      fmt::format(" {:.6g} apart, its local coordinates ask for {:.6g};", 2.5 * scale, std::sqrt(7.61) * scale));
    // Every distance agrees, but the other body holds P on the other side of A-B.
    check_model_error(scaled(two_bodies("[[4.0, 0.0], [2.0, -1.5], [0.0, 0.0]]"), scale), 25,
                      "body copy contradicts the other items: with it, joints A, B, P",
                      "; without it they hold its joints at its local distances but as their mirror image (B, A, P turn "
                      "counter-clockwise in 'local', clockwise in the others' pose);");
    // The body mirrored against its rough positions, beside links that follow them: said so, not "redundant".
    check_model_error(scaled(links_then_body("[2.0, -1.5]"), scale), 30, "body coupler contradicts the other items",
                      "(A, B, P turn clockwise in 'local', counter-clockwise in the others' pose);");
  }
}

TEST_CASE("Authoring checks: no shipped model warns, at any scale", "[linkage-authoring]") {
  for (const std::string& name : shipped_model_names()) {
    std::ifstream in(model_path(name));
    std::stringstream text;
    text << in.rdbuf();
    for (double scale : scales) {
      INFO(name << " at scale " << scale);
      const LinkageModel model(parse_linkage_description(scaled(text.str(), scale), name));
      CHECK_NOTHROW(check_driver_angles(model.description()));
      for (const AuthoringWarning& w : authoring_warnings(model, polished_reference(model, {}))) {
        FAIL_CHECK(warning_line(name, w));
      }
    }
  }
}
