#pragma once
// `numlab mechanism FILE --analyse`: the textbook analysis of a crank-driven four-bar or slider-crank,
// and the toggles and time ratio of any other crank-driven mechanism's output (a quick-return)
// (docs/linkage-files.md, "The four-bar and slider-crank analysis").
//
//  - the structure, read from the model: one crank O-A, one coupler A-B, one rocker Q-B and the
//    ground O-Q (each a [[link]] or a [[body]]; body points ride along), or a crank O-A, a rod A-S
//    and S on a [[slider]]. Anything else driven by a crank is analysed by its output alone (kind
//    "crank-driven": no classification, no closed forms); without an output it is "not a four-bar:
//    ..." and nothing is guessed;
//  - a four-bar's Grashof classification: s + l against p + q, and which link is the shortest;
//  - the driver's toggles (coupler and rocker in line), where d(crank)/d(output) vanishes: a fold of
//    the crank angle with no pose past it, where the velocity ratio is infinite. So the root is taken
//    of |AQ(theta)| - (b + c) and |AQ(theta)| - |b - c|, smooth in theta and monotone on each half-turn
//    from the direction of OQ: each half is a bracket, solved by GSL's Brent to 1e-10 rad (an end
//    within 1e-12 of the scale of zero is a change point the crank passes, not a toggle). A
//    slider-crank's: the rod normal to the line, |e - r sin(theta - beta)| = l;
//  - the output's toggles (dead centres), where its velocity ratio d(output)/d(crank) vanishes:
//    brackets where the ratio changes sign over a 1-degree sweep of the crank (from the reference pose
//    a turn, or up to the driver's toggles either way), each refined by Brent on the ratio at poses
//    solved to rounding, to 1e-10 rad (6e-9 deg);
//  - the time ratio of a crank that turns fully with two output toggles: the crank (turning the way
//    its angle grows) takes the slow stroke, 180 + alpha, one way between them and the quick stroke,
//    180 - alpha, back; ratio slow / quick = (180 + alpha) / (180 - alpha);
//  - beside each, the textbook closed form (law of cosines with b + a and b - a; for the
//    slider-crank l + r and l - r), for the reader to compare.

#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "numlab/mechanisms/linkage/linkage_solver.hpp"

namespace numlab::mechanisms {

struct Toggle {
  double crank_deg = 0.0;  // found by root finding, in [0, 360)
  double closed_form_deg = std::numeric_limits<double>::quiet_NaN();  // NaN: no closed form for this output
  std::string what;        // "crank and coupler extended in line", ...
  bool extended = false;   // an output toggle with crank and coupler (rod) extended; else folded
  double output_value = std::numeric_limits<double>::quiet_NaN();  // an output toggle: the output's angle
                                                                   // (deg) or slider travel there
};

struct CrankAnalysis {
  std::string kind;          // "four-bar", "slider-crank" or "crank-driven"; empty when not analysed
  std::string not_analysed;  // "not a four-bar: ..." when kind is empty or "crank-driven" (why it is not)
  std::string crank_name, coupler_name, rocker_name;  // link or body names (rocker empty for a slider-crank)
  double crank = 0.0, coupler = 0.0, rocker = 0.0, ground = 0.0;  // a, b, c, d (slider-crank: r, l, 0, offset e)
  // Four-bar: Grashof's condition s + l <= p + q.
  double shortest = 0.0, longest = 0.0, others = 0.0;  // s, l, p + q
  std::string shortest_name;   // "crank", "coupler", "rocker", "ground" (the first of equals in that order)
  std::string classification;  // "crank-rocker", "double-crank", "rocker-crank", "double-rocker",
                               // "change point", "triple-rocker (non-Grashof)"; slider-crank: "crank turns fully" or not
  bool grashof = false;
  std::string output;          // the output's name (a link or body, or a slider's joint)
  bool output_is_angle = false;  // a link's or body's angle (deg); else a slider joint's travel
  bool crank_turns_fully = false;
  std::vector<Toggle> driver_toggles, output_toggles;
  double alpha_deg = std::numeric_limits<double>::quiet_NaN();       // the time ratio's alpha
  double slow_stroke_deg = std::numeric_limits<double>::quiet_NaN(); // crank degrees: 180 + alpha
  double quick_stroke_deg = std::numeric_limits<double>::quiet_NaN();  // 180 - alpha
  int slow_stroke_start = -1;  // the slow stroke runs from output_toggles[k] to the other (crank growing)
  double time_ratio = std::numeric_limits<double>::quiet_NaN();      // slow / quick, from the toggles found
  double time_ratio_closed_form = std::numeric_limits<double>::quiet_NaN();
  int brent_iterations = 0;    // the most any root took
};

// The analysis of the solver's model on its reference branch. `output`: a link, body or slider joint
// name (find_output), empty for the default (the rocker, or the slider's joint; another crank-driven
// mechanism has none, and is then not analysed). Throws
// std::invalid_argument for an output the model does not have.
CrankAnalysis analyse_crank_mechanism(const LinkageSolver& solver, const std::string& output = {});

}  // namespace numlab::mechanisms
