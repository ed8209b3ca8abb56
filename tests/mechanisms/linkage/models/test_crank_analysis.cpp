// The four-bar and slider-crank analysis (crank_analysis.hpp): Grashof's classification, the toggles
// found by root finding against the law of cosines, the time ratio against (180 + alpha) / (180 - alpha),
// in the file's units, mm and km; and "not a four-bar" where the structure is another.

#include <catch2/catch.hpp>

#include <cmath>
#include <fmt/format.h>
#include <string>
#include <utility>

#include "four_bar_text.hpp"
#include "model_files.hpp"
#include "numlab/mechanisms/linkage/crank_analysis.hpp"

using namespace numlab::mechanisms;
using namespace numlab::mechanisms::testing;

namespace {

constexpr double to_deg = 180.0 / pi;

double gap_deg(double a, double b) { return std::abs(std::remainder(a - b, 360.0)); }

CrankAnalysis analyse_text(const std::string& text, const std::string& output = {}) {
  const LinkageModel model(parse_linkage_description(text, "fb.toml"));
  const LinkageSolver solver(model, {});
  return analyse_crank_mechanism(solver, output);
}

// A crank-rocker with ground along +x and B above it: the rocker's extremes where crank and coupler
// are in line, |OB| = b + a at crank phi1, |OB| = b - a at crank 180 + phi2 (law of cosines in O, Q, B).
void check_crank_rocker(const CrankAnalysis& r, double a, double b, double c, double d, const std::string& rocker = "rocker") {
  const double phi1 = std::acos((d * d + (a + b) * (a + b) - c * c) / (2 * d * (a + b))) * to_deg;
  const double phi2 = std::acos((d * d + (b - a) * (b - a) - c * c) / (2 * d * (b - a))) * to_deg;
  const double alpha = phi2 - phi1, ratio = (180 + alpha) / (180 - alpha);
  CHECK(r.kind == "four-bar");
  CHECK(r.classification == "crank-rocker");
  CHECK(r.grashof);
  CHECK(r.shortest_name == "crank");
  CHECK(r.crank_turns_fully);
  CHECK(r.driver_toggles.empty());
  CHECK(r.output == rocker);
  REQUIRE(r.output_toggles.size() == 2);
  INFO("found " << r.output_toggles[0].crank_deg << ", " << r.output_toggles[1].crank_deg << "; closed form " << phi1 << ", "
                << 180 + phi2);
  CHECK(gap_deg(r.output_toggles[0].crank_deg, phi1) < 1e-7);
  CHECK(r.output_toggles[0].extended);
  CHECK(gap_deg(r.output_toggles[1].crank_deg, 180 + phi2) < 1e-7);
  CHECK_FALSE(r.output_toggles[1].extended);
  CHECK(std::abs(r.alpha_deg - alpha) < 2e-7);
  CHECK(std::abs(r.time_ratio - ratio) < 1e-8);
  CHECK(std::abs(r.time_ratio_closed_form - ratio) < 1e-12);
}

// An offset slider-crank as text: crank r = |OA|, rod l = |AS|, S on the line y = e (along +x), every
// length times `scale`; reference pose the crank at `reference_deg` with S ahead of A. With `vee`, a
// second rod A-T of length `vee` drives T on the line x = 0 (a V-twin: two sliders, not a slider-crank).
std::string slider_crank_text(double r, double l, double e, double scale, double reference_deg = 30.0, double vee = 0.0,
                              const std::string& output = "") {
  const double t = reference_deg * pi / 180.0, ax = r * std::cos(t), ay = r * std::sin(t);
  const double sx = ax + std::sqrt(l * l - (e - ay) * (e - ay));
  std::string text = fmt::format("[linkage]\nname = \"sc\"\n{}[ground]\nO = [0.0, 0.0]\n[joints]\nA = [{:.17g}, {:.17g}]\n"
                                 "S = [{:.17g}, {:.17g}]\n",
                                 output.empty() ? "" : "output = \"" + output + "\"\n", ax * scale, ay * scale, sx * scale,
                                 e * scale);
  if (vee > 0.0) text += fmt::format("T = [0.0, {:.17g}]\n", (ay + std::sqrt(vee * vee - ax * ax)) * scale);
  text += fmt::format("[[link]]\njoints = [\"O\", \"A\"]\nlength = {:.17g}\n[[link]]\njoints = [\"A\", \"S\"]\nlength = {:.17g}\n"
                      "[[slider]]\njoint = \"S\"\nthrough = [0.0, {:.17g}]\nangle = 0.0\n",
                      r * scale, l * scale, e * scale);
  if (vee > 0.0) {
    text += fmt::format("[[link]]\njoints = [\"A\", \"T\"]\nlength = {:.17g}\n[[slider]]\njoint = \"T\"\nthrough = [0.0, 0.0]\n"
                        "angle = 90.0\n",
                        vee * scale);
  }
  return text + fmt::format("[driver]\ntype = \"crank\"\npivot = \"O\"\njoint = \"A\"\nangle = {:.17g}\n", reference_deg);
}

// A crank-rocker O-A-B-Q (ground d along +x) with a dyad hung on its rocker: a link B-C drives C on
// the line y = -1 (along +x). Three links and a rod on a slider: not a four-bar, but the rocker Q-B
// moves as the four-bar's, so its toggles have the four-bar's closed form.
std::string six_link_text(double a, double b, double c, double d, const std::string& output) {
  // The four-bar at crank 60 deg, B above the line A-Q (the circles about A and Q meet there).
  const double ax = a / 2.0, ay = a * std::sqrt(3.0) / 2.0, dx = d - ax, dy = -ay, e = std::hypot(dx, dy);
  const double along = (b * b - c * c + e * e) / (2.0 * e), h = std::sqrt(b * b - along * along);
  const double bx = ax + (along * dx - h * dy) / e, by = ay + (along * dy + h * dx) / e, rod = 6.0;
  const double cx = bx + std::sqrt(rod * rod - (by + 1.0) * (by + 1.0));
  return fmt::format(
      "[linkage]\nname = \"six\"\noutput = \"{}\"\n[ground]\nO = [0.0, 0.0]\nQ = [{:.17g}, 0.0]\n[joints]\n"
      "A = [{:.17g}, {:.17g}]\nB = [{:.17g}, {:.17g}]\nC = [{:.17g}, -1.0]\n"
      "[[link]]\njoints = [\"O\", \"A\"]\nlength = {:.17g}\n[[link]]\njoints = [\"A\", \"B\"]\nlength = {:.17g}\n"
      "[[link]]\njoints = [\"Q\", \"B\"]\nlength = {:.17g}\n[[link]]\njoints = [\"B\", \"C\"]\nlength = {:.17g}\n"
      "[[slider]]\njoint = \"C\"\nthrough = [0.0, -1.0]\nangle = 0.0\n"
      "[driver]\ntype = \"crank\"\npivot = \"O\"\njoint = \"A\"\nangle = 60.0\n",
      output, d, ax, ay, bx, by, cx, a, b, c, rod);
}

}  // namespace

TEST_CASE("A crank-rocker's toggles and time ratio by root finding match the law of cosines", "[crank-analysis]") {
  SECTION("four-bar.toml") {
    const LinkageModel model = model_file("four-bar");
    const LinkageSolver solver(model, {});
    check_crank_rocker(analyse_crank_mechanism(solver), 1.5, 4, 3.5, 4.5, "Q-B");
  }
  // 40, 120, 80, 100: s + l = 160 < p + q = 180, the crank shortest. phi1 = acos(0.9125) = 24.15 deg,
  // phi2 = acos(0.625) = 51.32 deg, alpha = 27.17 deg, time ratio 1.3556.
  SECTION("40, 120, 80, 100 mm") { check_crank_rocker(analyse_text(four_bar_text(40, 120, 80, 100, 1.0)), 40, 120, 80, 100); }
  SECTION("the same in km") { check_crank_rocker(analyse_text(four_bar_text(40, 120, 80, 100, 1e-6)), 40, 120, 80, 100); }
  SECTION("the same, 1e6 times larger") {
    check_crank_rocker(analyse_text(four_bar_text(40, 120, 80, 100, 1e6)), 40, 120, 80, 100);
  }
  SECTION("the reference pose elsewhere on the turn") {
    check_crank_rocker(analyse_text(four_bar_text(40, 120, 80, 100, 1.0, 250.0)), 40, 120, 80, 100);
  }
}

TEST_CASE("Grashof's classification names the kind by the shortest link", "[crank-analysis]") {
  // Ground shortest: a double-crank, no toggles, no time ratio.
  const CrankAnalysis double_crank = analyse_text(four_bar_text(3, 4, 3.5, 1.5, 1.0));
  CHECK(double_crank.classification == "double-crank");
  CHECK(double_crank.shortest_name == "ground");
  CHECK(double_crank.crank_turns_fully);
  CHECK(double_crank.output_toggles.empty());
  CHECK(std::isnan(double_crank.time_ratio));
  // Coupler shortest: a Grashof double-rocker; the crank stops where coupler and rocker line up.
  const CrankAnalysis double_rocker = analyse_text(four_bar_text(3, 1.5, 3.5, 4, 1.0, 90.0));
  CHECK(double_rocker.classification == "double-rocker");
  CHECK(double_rocker.grashof);
  CHECK_FALSE(double_rocker.crank_turns_fully);
  // The parallelogram: s + l = p + q, a change point.
  CHECK(analyse_text(four_bar_text(2, 4, 2, 4, 1.0)).classification == "change point");
}

TEST_CASE("A non-Grashof four-bar's crank stops at its toggles: arccos((a^2 + d^2 - (b + c)^2) / 2ad)", "[crank-analysis]") {
  // Crank 2, coupler 3, rocker 2.5, ground 4 (docs/linkage-files.md's limit example): s + l = 6 > 5.5.
  for (double scale : {1.0, 1e-6, 1e6}) {
    const CrankAnalysis r = analyse_text(four_bar_text(2, 3, 2.5, 4, scale));
    const double toggle = std::acos((4.0 + 16.0 - 5.5 * 5.5) / 16.0) * to_deg;  // 129.838 deg
    CHECK(r.classification == "triple-rocker (non-Grashof)");
    CHECK_FALSE(r.grashof);
    CHECK_FALSE(r.crank_turns_fully);
    REQUIRE(r.driver_toggles.size() == 2);  // |b - c| = 0.5 is never reached: (4 + 16 - 0.25) / 16 > 1
    CHECK(gap_deg(r.driver_toggles[0].crank_deg, toggle) < 1e-7);
    CHECK(gap_deg(r.driver_toggles[1].crank_deg, -toggle) < 1e-7);
    CHECK(std::isnan(r.time_ratio));
    // The rocker's extremes inside that range: crank and coupler in line, |OB| = a + b = 5 (|OB| = 1
    // cannot close with the rocker): crank at +-acos((16 + 25 - 6.25) / 40) = +-29.66 deg.
    const double extended = std::acos((16.0 + 25.0 - 6.25) / 40.0) * to_deg;
    REQUIRE_FALSE(r.output_toggles.empty());
    for (const Toggle& t : r.output_toggles) {
      CHECK(std::min(gap_deg(t.crank_deg, extended), gap_deg(t.crank_deg, -extended)) < 1e-7);
      CHECK(t.extended);
    }
  }
}

TEST_CASE("The offset slider-crank's dead centres and quick-return ratio match the closed form", "[crank-analysis]") {
  // r = 1, l = 3.2, e = 0.4: extended at atan2(e, sqrt((l + r)^2 - e^2)) = 5.465 deg, folded at
  // 180 + atan2(e, sqrt((l - r)^2 - e^2)) = 190.476 deg; alpha = 5.011 deg, time ratio 1.0573.
  const LinkageModel model = model_file("slider-crank");
  const LinkageSolver solver(model, {});
  const CrankAnalysis r = analyse_crank_mechanism(solver);
  const double ext = std::atan2(0.4, std::sqrt(4.2 * 4.2 - 0.16)) * to_deg;
  const double fold = 180.0 + std::atan2(0.4, std::sqrt(2.2 * 2.2 - 0.16)) * to_deg;
  const double alpha = fold - ext - 180.0;
  CHECK(r.kind == "slider-crank");
  CHECK(r.output == "S");
  CHECK(r.crank_turns_fully);
  CHECK(r.driver_toggles.empty());
  REQUIRE(r.output_toggles.size() == 2);
  CHECK(gap_deg(r.output_toggles[0].crank_deg, ext) < 1e-7);
  CHECK(gap_deg(r.output_toggles[1].crank_deg, fold) < 1e-7);
  CHECK(gap_deg(r.output_toggles[0].closed_form_deg, ext) < 1e-10);
  CHECK(std::abs(r.time_ratio - (180 + alpha) / (180 - alpha)) < 1e-8);
}

TEST_CASE("A mechanism that is not a four-bar is said to be one, and not analysed", "[crank-analysis]") {
  for (const std::string name : {"jansen", "watt-i", "klann"}) {
    const LinkageModel model = model_file(name);
    const LinkageSolver solver(model, {});
    const CrankAnalysis r = analyse_crank_mechanism(solver);
    INFO(name << ": " << r.not_analysed);
    CHECK(r.kind.empty());
    CHECK(r.not_analysed.rfind("not a four-bar: ", 0) == 0);
  }
  const LinkageModel model = model_file("four-bar");
  const LinkageSolver solver(model, {});
  CHECK_THROWS_WITH(analyse_crank_mechanism(solver, "X"),
                    "unknown output 'X': name one of the links O-A, A-B, Q-B");
  // Another output: the coupler stands still (omega 0) at its own toggles; no closed form is claimed.
  const CrankAnalysis coupler = analyse_crank_mechanism(solver, "A-B");
  CHECK(coupler.output == "A-B");
  for (const Toggle& t : coupler.output_toggles) CHECK(std::isnan(t.closed_form_deg));
}

namespace {

// The four-bar of four_bar_text with its ground line O-Q turned `gamma_deg` from +x.
std::string tilted_four_bar_text(double a, double b, double c, double d, double gamma_deg, double reference_deg) {
  const double g = gamma_deg * pi / 180.0, t = reference_deg * pi / 180.0;
  const double qx = d * std::cos(g), qy = d * std::sin(g), ax = a * std::cos(t), ay = a * std::sin(t);
  const double dx = qx - ax, dy = qy - ay, e = std::hypot(dx, dy);
  const double along = (b * b - c * c + e * e) / (2.0 * e), h = std::sqrt(b * b - along * along);
  return fmt::format(
      "[linkage]\nname = \"tilted\"\n[ground]\nO = [0.0, 0.0]\nQ = [{:.17g}, {:.17g}]\n[joints]\nA = [{:.17g}, {:.17g}]\n"
      "B = [{:.17g}, {:.17g}]\n[[link]]\njoints = [\"O\", \"A\"]\nlength = {:.17g}\n[[link]]\njoints = [\"A\", \"B\"]\n"
      "length = {:.17g}\n[[link]]\njoints = [\"Q\", \"B\"]\nlength = {:.17g}\n[driver]\ntype = \"crank\"\npivot = \"O\"\n"
      "joint = \"A\"\nangle = {:.17g}\n",
      qx, qy, ax, ay, ax + (along * dx - h * dy) / e, ay + (along * dy + h * dx) / e, a, b, c, reference_deg);
}

// The crank angles (deg) where |AQ| = L, Q at distance d in direction gamma: the law of cosines,
// cos(theta - gamma) = (a^2 + d^2 - L^2) / 2ad.
std::pair<double, double> law_of_cosines_toggles(double a, double d, double L, double gamma_deg) {
  const double phi = std::acos((a * a + d * d - L * L) / (2.0 * a * d)) * to_deg;
  return {gamma_deg + phi, gamma_deg - phi};
}

bool crank_between(double crank, double lo, double hi) {  // lo < hi, unwrapped degrees
  for (double k : {-360.0, 0.0, 360.0}) {
    if (crank + k >= lo && crank + k <= hi) return true;
  }
  return false;
}

}  // namespace

TEST_CASE("A Grashof double-rocker's driver toggles are the roots of |AQ| - (b + c) and |AQ| - |b - c|", "[crank-analysis]") {
  // Crank 3, coupler 1.5, rocker 3.5, ground 4: |AQ|^2 = 25 - 24 cos(theta). |AQ| = b + c = 5 at
  // theta = +-90 deg; |AQ| = c - b = 2 at theta = +-acos(21/24) = +-28.955 deg.
  for (double scale : {1.0, 1e-6, 1e6}) {
    INFO("scale " << scale);
    const CrankAnalysis r = analyse_text(four_bar_text(3, 1.5, 3.5, 4, scale, 60.0));
    const auto [extended_up, extended_down] = law_of_cosines_toggles(3, 4, 5, 0);
    const auto [folded_up, folded_down] = law_of_cosines_toggles(3, 4, 2, 0);
    CHECK(r.classification == "double-rocker");
    CHECK_FALSE(r.crank_turns_fully);
    REQUIRE(r.driver_toggles.size() == 4);
    const double expected[] = {folded_up, extended_up, 360.0 + extended_down, 360.0 + folded_down};  // sorted
    for (std::size_t k = 0; k < 4; ++k) {
      INFO("toggle " << k << ": found " << r.driver_toggles[k].crank_deg << ", law of cosines " << expected[k]);
      CHECK(gap_deg(r.driver_toggles[k].crank_deg, expected[k]) < 1e-7);
      CHECK(gap_deg(r.driver_toggles[k].closed_form_deg, expected[k]) < 1e-9);
      CHECK(r.driver_toggles[k].what == (k == 0 || k == 3 ? "coupler and rocker folded in line" : "coupler and rocker extended in line"));
    }
    // The reference pose (60 deg) lies between 28.955 and 90: the output's toggles, if any, too.
    for (const Toggle& t : r.output_toggles) CHECK(crank_between(t.crank_deg, folded_up, extended_up));
    CHECK(std::isnan(r.time_ratio));
  }
}

TEST_CASE("Two driver toggles 0.44 deg apart are both found, and the crank does not turn fully", "[crank-analysis]") {
  // Crank 2, coupler 3, rocker 2.99999, ground 4 turned 0.5 deg: |AQ| = b + c = 5.99999 just short of
  // a + d = 6, at 0.5 + 180 -+ 0.2214 deg; the crank turns all the turn but that 0.44-degree gap,
  // which a 1-degree grid of brackets would step over (both roots in [180, 181]).
  const CrankAnalysis r = analyse_text(tilted_four_bar_text(2, 3, 2.99999, 4, 0.5, 60.0));
  const auto [up, down] = law_of_cosines_toggles(2, 4, 5.99999, 0.5);
  INFO("law of cosines: " << up << ", " << 360.0 + down);
  CHECK(std::abs(up + down - 2 * 0.5) < 1e-9);  // symmetric about 180.5
  CHECK(360.0 + down - up < 0.45);
  CHECK_FALSE(r.crank_turns_fully);
  REQUIRE(r.driver_toggles.size() == 2);
  CHECK(gap_deg(r.driver_toggles[0].crank_deg, up) < 1e-7);
  CHECK(gap_deg(r.driver_toggles[1].crank_deg, down) < 1e-7);

  // Every output toggle on the branch lies outside the gap, and there is no time ratio.
  for (const Toggle& t : r.output_toggles) CHECK_FALSE(crank_between(t.crank_deg, up, 360.0 + down));
  CHECK(std::isnan(r.time_ratio));
}

TEST_CASE("A change point's flat poses are not toggles: the parallelogram's crank turns fully", "[crank-analysis]") {
  // 2, 4, 2, 4: |AQ| reaches b + c = 6 at crank 180 and |b - c| = 2 at crank 0, but only touches them.
  const CrankAnalysis r = analyse_text(four_bar_text(2, 4, 2, 4, 1.0));
  CHECK(r.classification == "change point");
  CHECK(r.driver_toggles.empty());
  CHECK(r.crank_turns_fully);
}

TEST_CASE("A slider-crank whose crank cannot turn stops where the rod is normal to the line", "[crank-analysis]") {
  // r = 2, l = 1.5, e = 0.4: h = e - r sin(theta) = +-l at sin(theta) = (0.4 -+ 1.5) / 2 = -0.55, 0.95.
  for (double scale : {1.0, 1e-3, 1e3}) {
    const CrankAnalysis r = analyse_text(slider_crank_text(2, 1.5, 0.4, scale));
    const double low = std::asin(-0.55) * to_deg, high = std::asin(0.95) * to_deg;  // -33.367, 71.805
    CHECK(r.kind == "slider-crank");
    CHECK_FALSE(r.crank_turns_fully);
    REQUIRE(r.driver_toggles.size() == 4);
    const double expected[] = {high, 180.0 - high, 180.0 - low, 360.0 + low};
    for (std::size_t k = 0; k < 4; ++k) {
      INFO("scale " << scale << ", toggle " << k << ": " << r.driver_toggles[k].crank_deg << " against " << expected[k]);
      CHECK(gap_deg(r.driver_toggles[k].crank_deg, expected[k]) < 1e-7);
      CHECK(gap_deg(r.driver_toggles[k].closed_form_deg, expected[k]) < 1e-9);
    }
    for (const Toggle& t : r.output_toggles) CHECK(crank_between(t.crank_deg, low, high));
  }
}

TEST_CASE("Any crank-driven mechanism: the output's toggles by Brent on its velocity ratio, time ratio slow / quick", "[crank-analysis]") {
  SECTION("a V-twin's first slider: the offset slider-crank's dead centres") {
    // slider-crank.toml's r = 1, l = 3.2, e = 0.4 and a second rod to a slider on x = 0: two sliders,
    // so not a slider-crank; S still stops where crank and rod are in line (5.465, 190.476 deg).
    for (double scale : {1.0, 1e-3, 1e3}) {
      INFO("scale " << scale);
      const CrankAnalysis r = analyse_text(slider_crank_text(1, 3.2, 0.4, scale, 30.0, 3.0, "S"));
      const double ext = std::atan2(0.4, std::sqrt(4.2 * 4.2 - 0.16)) * to_deg;
      const double fold = 180.0 + std::atan2(0.4, std::sqrt(2.2 * 2.2 - 0.16)) * to_deg;
      const double slow = fold - ext, quick = 360.0 - slow;
      CHECK(r.kind == "crank-driven");
      CHECK(r.not_analysed == "not a four-bar: 2 sliders");
      CHECK(r.crank_name == "O-A");
      CHECK(r.crank == Approx(scale));
      CHECK(r.crank_turns_fully);
      CHECK_FALSE(r.output_is_angle);
      REQUIRE(r.output_toggles.size() == 2);
      CHECK(gap_deg(r.output_toggles[0].crank_deg, ext) < 1e-7);
      CHECK(gap_deg(r.output_toggles[1].crank_deg, fold) < 1e-7);
      CHECK(std::isnan(r.output_toggles[0].closed_form_deg));  // no closed form is claimed
      // The slider's travel there: x = sqrt((l +- r)^2 - e^2).
      CHECK(std::abs(r.output_toggles[0].output_value - std::sqrt(4.2 * 4.2 - 0.16) * scale) < 1e-9 * scale);
      CHECK(std::abs(r.output_toggles[1].output_value - std::sqrt(2.2 * 2.2 - 0.16) * scale) < 1e-9 * scale);
      CHECK(std::abs(r.slow_stroke_deg - slow) < 2e-7);
      CHECK(std::abs(r.quick_stroke_deg - quick) < 2e-7);
      CHECK(r.slow_stroke_start == 0);  // from the extended dead centre to the folded one, crank growing
      CHECK(std::abs(r.time_ratio - slow / quick) < 1e-8);
      CHECK(std::abs(r.alpha_deg - (slow - 180.0)) < 2e-7);
    }
  }
  SECTION("the V-twin's second slider, on a line through O: dead centres at 90 and 270, ratio 1") {
    const CrankAnalysis r = analyse_text(slider_crank_text(1, 3.2, 0.4, 1.0, 30.0, 3.0, "T"));
    REQUIRE(r.output_toggles.size() == 2);
    CHECK(gap_deg(r.output_toggles[0].crank_deg, 90.0) < 1e-7);
    CHECK(gap_deg(r.output_toggles[1].crank_deg, 270.0) < 1e-7);
    CHECK(std::abs(r.time_ratio - 1.0) < 1e-8);
  }
  SECTION("a crank-rocker with a dyad on its rocker: the rocker's toggles are the four-bar's") {
    // four-bar.toml's 1.5, 4, 3.5, 4.5 (39.400568754 and 230.703519761 deg, time ratio 1.134002949).
    const CrankAnalysis r = analyse_text(six_link_text(1.5, 4, 3.5, 4.5, "Q-B"));
    const double phi1 = std::acos((4.5 * 4.5 + 5.5 * 5.5 - 3.5 * 3.5) / (2 * 4.5 * 5.5)) * to_deg;
    const double phi2 = std::acos((4.5 * 4.5 + 2.5 * 2.5 - 3.5 * 3.5) / (2 * 4.5 * 2.5)) * to_deg;
    const double alpha = phi2 - phi1;
    CHECK(r.kind == "crank-driven");
    CHECK(r.crank_turns_fully);
    CHECK(r.output_is_angle);
    REQUIRE(r.output_toggles.size() == 2);
    CHECK(gap_deg(r.output_toggles[0].crank_deg, phi1) < 1e-7);
    CHECK(gap_deg(r.output_toggles[1].crank_deg, 180 + phi2) < 1e-7);
    CHECK(std::abs(r.time_ratio - (180 + alpha) / (180 - alpha)) < 1e-8);
    // The rocker's angle at its extremes: B where |OB| = b + a, from the law of cosines at Q.
    const double at_q = std::acos((4.5 * 4.5 + 3.5 * 3.5 - 5.5 * 5.5) / (2 * 4.5 * 3.5)) * to_deg;
    CHECK(std::abs(r.output_toggles[0].output_value - (180.0 - at_q)) < 1e-7);
  }
  SECTION("a non-Grashof four-bar with the dyad: the crank does not turn fully, no time ratio") {
    const CrankAnalysis r = analyse_text(six_link_text(2, 3, 2.5, 4, "Q-B"));
    CHECK(r.kind == "crank-driven");
    CHECK_FALSE(r.crank_turns_fully);
    CHECK(r.classification.rfind("the crank does not turn fully", 0) == 0);
    CHECK(std::isnan(r.time_ratio));
    const double extended = std::acos((16.0 + 25.0 - 6.25) / 40.0) * to_deg;  // as the four-bar's: 29.686 deg
    REQUIRE_FALSE(r.output_toggles.empty());
    for (const Toggle& t : r.output_toggles) CHECK(std::min(gap_deg(t.crank_deg, extended), gap_deg(t.crank_deg, -extended)) < 1e-7);
  }
  SECTION("without an output nothing is guessed") {
    const CrankAnalysis r = analyse_text(slider_crank_text(1, 3.2, 0.4, 1.0, 30.0, 3.0));
    CHECK(r.kind.empty());
    CHECK(r.not_analysed == "not a four-bar: 2 sliders; name an output (--output or the file's output) for its toggles and time ratio");
  }
}

namespace {

// A Whitworth quick-return as text: the crank O2-A (r) about O2 = (0, d), the slotted link O4-B (R)
// about O4 = (0, 0) with the block at A in its slot, the rod B-C (l) and the ram C on the line y = 0
// through O4; every length times `scale`, the reference pose at crank `reference_deg`.
std::string whitworth_text(double r, double d, double R, double l, double scale, double reference_deg) {
  const double t = reference_deg * pi / 180.0, ax = r * std::cos(t), ay = d + r * std::sin(t), s = std::hypot(ax, ay);
  const double bx = R * ax / s, by = R * ay / s, cx = bx + std::sqrt(l * l - by * by);
  return fmt::format(
      "[linkage]\nname = \"w\"\noutput = \"C\"\n[ground]\nO2 = [0.0, {:.17g}]\nO4 = [0.0, 0.0]\n[joints]\nA = [{:.17g}, {:.17g}]\n"
      "B = [{:.17g}, {:.17g}]\nC = [{:.17g}, 0.0]\n[[link]]\njoints = [\"O2\", \"A\"]\nlength = {:.17g}\n[[link]]\n"
      "joints = [\"O4\", \"B\"]\nlength = {:.17g}\n[[link]]\njoints = [\"B\", \"C\"]\nlength = {:.17g}\n[[slider]]\njoint = \"A\"\n"
      "line = [\"O4\", \"B\"]\n[[slider]]\njoint = \"C\"\nthrough = [0.0, 0.0]\nangle = 0.0\n[driver]\ntype = \"crank\"\n"
      "pivot = \"O2\"\njoint = \"A\"\nangle = {:.17g}\n",
      d * scale, ax * scale, ay * scale, bx * scale, by * scale, cx * scale, r * scale, R * scale, l * scale, reference_deg);
}

// An inverted slider-crank (the crank-shaper): the crank O-A (r) about O = (0, 0), the rocker B-C (L)
// about B = d (cos g, sin g), the block at A sliding along B-C; every length times `scale`.
std::string crank_shaper_text(double r, double d, double g_deg, double L, double scale, double reference_deg) {
  const double t = reference_deg * pi / 180.0, g = g_deg * pi / 180.0;
  const double ax = r * std::cos(t), ay = r * std::sin(t), bx = d * std::cos(g), by = d * std::sin(g);
  const double s = std::hypot(ax - bx, ay - by), cx = bx + L * (ax - bx) / s, cy = by + L * (ay - by) / s;
  return fmt::format(
      "[linkage]\nname = \"cs\"\noutput = \"rocker\"\n[ground]\nO = [0.0, 0.0]\nB = [{:.17g}, {:.17g}]\n[joints]\n"
      "A = [{:.17g}, {:.17g}]\nC = [{:.17g}, {:.17g}]\n[[link]]\njoints = [\"O\", \"A\"]\nlength = {:.17g}\n[[link]]\n"
      "name = \"rocker\"\njoints = [\"B\", \"C\"]\nlength = {:.17g}\n[[slider]]\njoint = \"A\"\nline = [\"B\", \"C\"]\n"
      "[driver]\ntype = \"crank\"\npivot = \"O\"\njoint = \"A\"\nangle = {:.17g}\n",
      bx * scale, by * scale, ax * scale, ay * scale, cx * scale, cy * scale, r * scale, L * scale, reference_deg);
}

// Whitworth, r > d: the ram's line passes through O4, so C stands still exactly when the slot lies
// along it (C_x = R cos phi + sqrt(l^2 - R^2 sin^2 phi) has C_x' = -R sin phi (1 + R cos phi / q) = 0
// only at sin phi = 0): A on y = 0, r sin theta = -d, theta = -beta and 180 + beta, beta = asin(d / r).
// Crank growing, the ram goes out from the first (C = R + l) ... the strokes 180 + 2 beta (A above
// O4: the slot turns slowly) and 180 - 2 beta; C at l + R and l - R.
void check_whitworth(const CrankAnalysis& a, double r, double d, double R, double l, double scale) {
  const double beta = std::asin(d / r) * to_deg;
  CHECK(a.kind == "crank-driven");
  CHECK(a.crank_turns_fully);
  CHECK(a.output == "C");
  REQUIRE(a.output_toggles.size() == 2);
  INFO("found " << a.output_toggles[0].crank_deg << ", " << a.output_toggles[1].crank_deg << "; closed form " << 180 + beta
                << ", " << 360 - beta);
  CHECK(gap_deg(a.output_toggles[0].crank_deg, 180.0 + beta) < 1e-7);
  CHECK(gap_deg(a.output_toggles[1].crank_deg, -beta) < 1e-7);
  CHECK(std::abs(a.output_toggles[0].output_value - (l - R) * scale) < 1e-9 * l * scale);
  CHECK(std::abs(a.output_toggles[1].output_value - (l + R) * scale) < 1e-9 * l * scale);
  CHECK(std::abs(a.slow_stroke_deg - (180.0 + 2.0 * beta)) < 2e-7);
  CHECK(std::abs(a.quick_stroke_deg - (180.0 - 2.0 * beta)) < 2e-7);
  CHECK(a.slow_stroke_start == 1);  // from -beta (C = l + R) over the top to 180 + beta (C = l - R)
  CHECK(std::abs(a.time_ratio - (180.0 + 2.0 * beta) / (180.0 - 2.0 * beta)) < 1e-8);
}

// Crank-shaper, r < d: the rocker B-A stands still where it is tangent to the crank circle, BA
// perpendicular to OA: the crank at the direction of OB -+ gamma, gamma = acos(r / d). The crank
// turns 2 gamma on B's side (the quick stroke) and 360 - 2 gamma = 180 + 2 asin(r / d) away from B
// (the slow one); the rocker's angle there is the direction of BO -+ asin(r / d).
void check_crank_shaper(const CrankAnalysis& a, double r, double d, double g_deg) {
  const double gamma = std::acos(r / d) * to_deg, swing = std::asin(r / d) * to_deg;
  CHECK(a.kind == "crank-driven");
  CHECK(a.crank_turns_fully);
  CHECK(a.output_is_angle);
  REQUIRE(a.output_toggles.size() == 2);
  const double lo = g_deg - gamma, hi = g_deg + gamma;  // the toggles, in either order once wrapped
  INFO("found " << a.output_toggles[0].crank_deg << ", " << a.output_toggles[1].crank_deg << "; closed form " << lo << ", " << hi);
  CHECK(std::min(gap_deg(a.output_toggles[0].crank_deg, lo), gap_deg(a.output_toggles[0].crank_deg, hi)) < 1e-7);
  CHECK(std::min(gap_deg(a.output_toggles[1].crank_deg, lo), gap_deg(a.output_toggles[1].crank_deg, hi)) < 1e-7);
  for (const Toggle& t : a.output_toggles) {
    const bool at_lo = gap_deg(t.crank_deg, lo) < 1e-6;
    CHECK(gap_deg(t.output_value, g_deg + 180.0 + (at_lo ? swing : -swing)) < 1e-7);
  }
  CHECK(std::abs(a.slow_stroke_deg - (180.0 + 2.0 * swing)) < 2e-7);
  CHECK(std::abs(a.slow_stroke_deg - (360.0 - 2.0 * gamma)) < 2e-7);
  CHECK(std::abs(a.time_ratio - (180.0 - gamma) / gamma) < 1e-8);
  // The slow stroke starts at the toggle from which the crank, growing, turns away from B.
  const double start = a.output_toggles[static_cast<std::size_t>(a.slow_stroke_start)].crank_deg;
  CHECK(gap_deg(start, hi) < 1e-6);
}

}  // namespace

TEST_CASE("A Whitworth quick-return's ram toggles and time ratio match (180 + 2 beta) / (180 - 2 beta)", "[crank-analysis]") {
  SECTION("the shipped whitworth.toml: r = 100, |O2 O4| = 45 mm, slot 160, rod 450") {
    const LinkageModel model = model_file("whitworth");
    const LinkageSolver solver(model, {});
    const CrankAnalysis a = analyse_crank_mechanism(solver);  // the file's output, C
    check_whitworth(a, 100, 45, 160, 450, 1.0);
    CHECK(a.time_ratio == Approx(1.845565648).epsilon(1e-9));  // beta = 26.7437 deg
  }
  for (double scale : {1e-3, 1e3}) {
    for (double reference : {30.0, 250.0}) {
      INFO("scale " << scale << ", reference " << reference);
      check_whitworth(analyse_text(whitworth_text(100, 70, 160, 450, scale, reference)), 100, 70, 160, 450, scale);
    }
  }
}

TEST_CASE("A crank-shaper's rocker toggles where it is tangent to the crank circle: slow stroke 180 + 2 asin(r / d)", "[crank-analysis]") {
  SECTION("the shipped inverted-slider-crank.toml: r = 40, B 100 mm below O") {
    const LinkageModel model = model_file("inverted-slider-crank");
    const LinkageSolver solver(model, {});
    const CrankAnalysis a = analyse_crank_mechanism(solver);  // the file's output, the rocker
    check_crank_shaper(a, 40, 100, -90);
    CHECK(a.time_ratio == Approx(1.709952782).epsilon(1e-9));
  }
  for (double scale : {1e-3, 1e3}) {
    INFO("scale " << scale);
    check_crank_shaper(analyse_text(crank_shaper_text(60, 100, -70, 220, scale, 10.0)), 60, 100, -70);
    check_crank_shaper(analyse_text(crank_shaper_text(30, 100, 35, 220, scale, 200.0)), 30, 100, 35);
  }
}
