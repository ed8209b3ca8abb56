// Lab `basins`: the z^3 - 1 Newton fractal, the four-bar's two assembly modes with the toggle line
// between them, and the Jansen leg's branches on a slice through the seed's solution: where the
// seed's estimates sit, how far a start may stray, and what damping changes. Every sentence is
// built (basin_sentences.hpp) from the numbers in the table printed beside it.

#include "lessons/lab_basins.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <thread>

#include "basins/basin_chart.hpp"
#include "basins/basin_run.hpp"
#include "basins/basin_sentences.hpp"
#include "basins/basin_systems.hpp"

namespace numlab::cli {

namespace {

using basins::BasinRun;
using basins::BasinTally;

int all_cores() { return std::max(1, static_cast<int>(std::thread::hardware_concurrency())); }

BasinRun map_of(const std::string& system, int side, bool damped) {
  basins::BasinRequest request;
  request.system = system;
  request.columns = request.rows = side;
  request.damped = damped;
  request.threads = all_cores();
  return basins::run_basins(request);
}

void add_outcome_rows(Table& table, const BasinRun& run) {
  const BasinTally counts = basins::tally(run.map, static_cast<int>(run.mode_labels.size()));
  for (std::size_t mode = 0; mode < counts.per_mode.size(); ++mode) {
    if (counts.per_mode[mode] > 0) {
      table.add_row({run.mode_labels[mode], std::to_string(counts.per_mode[mode]),
                     basins::percent(counts.per_mode[mode], counts.total)});
    }
  }
  const std::vector<std::pair<std::string, int>> others = {
      {"root of no known mode", counts.unknown}, {"diverged", counts.diverged},     {"singular", counts.singular},
      {"max_iterations", counts.max_iterations}, {"non_finite", counts.non_finite}, {"no_progress", counts.no_progress}};
  for (const auto& [name, count] : others) {
    if (count > 0) table.add_row({name, std::to_string(count), basins::percent(count, counts.total)});
  }
}

int failed(const BasinTally& t) { return t.diverged + t.singular + t.max_iterations + t.non_finite + t.no_progress; }

void chart(LabSession& session, const std::string& name, const BasinRun& run, const std::string& title,
           const std::string& caption) {
  ensure_directory(session.folder());
  const ChartFiles files = chart_files(session.folder() + "/" + name + ".png");
  basins::draw_basin_chart(files, run, title);
  session.figure(files.chart, caption);
}

// The grid point nearest (u, v) on the map.
const nonlinear::BasinPoint& nearest_point(const nonlinear::BasinMap& map, double u, double v) {
  const auto& s = map.slice;
  const auto index = [](double x, double low, double high, int n) {
    return std::clamp(static_cast<int>(std::lround((x - low) / (high - low) * (n - 1))), 0, n - 1);
  };
  return map.at(index(u, s.u_min, s.u_max, s.columns), index(v, s.v_min, s.v_max, s.rows));
}

// The map of a two-unknown system, its outcome table shown and saved as NAME.csv, and its tally.
BasinTally map_and_table(LabSession& session, const std::string& system, const std::string& name, BasinRun& run) {
  run = map_of(system, basins_lab_grid + 1, false);
  Table table({"outcome", "starts", "share"});
  add_outcome_rows(table, run);
  session.show(table, name);
  return basins::tally(run.map, static_cast<int>(run.mode_labels.size()));
}

void fractal_step(LabSession& session) {
  const int side = basins_lab_grid + 1;
  if (!session.begin_step("The z^3 - 1 Newton fractal",
                          fmt::format("z^3 = 1 written as two real equations in x and y, Newton from each of {} x {} "
                                      "starts on [-2, 2] x [-2, 2]. Each start is coloured by the cube root of unity it "
                                      "reaches (checked against e^(2 pi i k/3)), lighter the more iterations it took.",
                                      side, side))) return;
  BasinRun run;
  const BasinTally t = map_and_table(session, "fractal", "fractal", run);
  session.say(basins::fractal_sentence(t.per_mode[0], t.per_mode[1], t.per_mode[2], failed(t), t.total));
  const auto& origin = run.map.at(side / 2, side / 2);
  session.say(fmt::format("The start at the origin ends {}: there J = 3 z^2 is the zero matrix.",
                          to_string(origin.status)));
  chart(session, "step1-fractal", run, fmt::format("z^3 - 1: plain Newton from {} x {} starts", side, side),
        "Newton's basins of the three cube roots of unity");
}

void four_bar_step(LabSession& session) {
  const int side = basins_lab_grid + 1;
  if (!session.begin_step("A four-bar's two assembly modes and the toggle line",
                          fmt::format("A Grashof four-bar (crank 2, coupler 7, rocker 5, ground 6) at a crank angle of 60 "
                                      "degrees: the unknowns are the coupler angle theta3 and the rocker angle theta4, "
                                      "each over a whole turn on a {} x {} grid. The coupler-rocker joint B lies left (B+) "
                                      "or right (B-) of the line from the crank tip A to the rocker pivot O4, each mode "
                                      "checked against the circle-circle intersection. The dashed lines are where J is "
                                      "singular, theta3 - theta4 = k pi: a start there has no Newton step.",
                                      side, side))) return;
  BasinRun run;
  const BasinTally t = map_and_table(session, "four-bar", "four-bar", run);
  session.say(basins::four_bar_sentence(t.per_mode[0], t.per_mode[1], t.singular, failed(t), t.total));
  chart(session, "step2-four-bar", run, fmt::format("Grashof four-bar at 60 deg: plain Newton from {} x {} starts", side, side),
        "The four-bar's two modes, and the toggle lines where J is singular");
}

void jansen_step(LabSession& session) {
  const int side = basins_lab_grid;
  if (!session.begin_step("The Jansen leg's branches on a slice through the seed's solution",
                          fmt::format("The 8-angle closure at the seed's crank angle, 1.57 rad. theta1 (A->B) and theta7 "
                                      "(P1->D) run over a whole turn around the seed's solution on a {} x {} grid; the other "
                                      "six angles stay at the solution. A mode is the side of each of the four dyads B, C, "
                                      "D, E (16 branches), each checked against that branch's circle intersections. "
                                      "Plain Newton, then damped Newton (backtracking on ||f||^2), at most 20 iterations.",
                                      side, side))) return;
  const BasinRun plain = map_of("jansen", side, false), damped = map_of("jansen", side, true);
  const int home = plain.home_mode;
  const BasinTally p = basins::tally(plain.map, 16), d = basins::tally(damped.map, 16);
  Table modes({"outcome", "plain starts", "plain share", "damped starts", "damped share"});
  const auto add = [&](const std::string& name, int a, int b) {
    if (a > 0 || b > 0) modes.add_row({name, std::to_string(a), basins::percent(a, p.total), std::to_string(b), basins::percent(b, d.total)});
  };
  for (int mode = 0; mode < 16; ++mode) add(plain.mode_labels[mode] + (mode == home ? " (seed's)" : ""), p.per_mode[mode], d.per_mode[mode]);
  add("root of no known mode", p.unknown, d.unknown);
  add("diverged", p.diverged, d.diverged);
  add("singular", p.singular, d.singular);
  add("max_iterations", p.max_iterations, d.max_iterations);
  add("non_finite", p.non_finite, d.non_finite);
  add("no_progress", p.no_progress, d.no_progress);
  session.show(modes, "jansen-modes");

  const basins::SliceMark& solution = plain.marks[0];
  const basins::SliceMark& estimate = plain.marks[1];
  const double estimate_distance = std::hypot(estimate.u - solution.u, estimate.v - solution.v);
  const bool estimate_home = nearest_point(plain.map, estimate.u, estimate.v).mode == home;
  const double step = (plain.map.slice.u_max - plain.map.slice.u_min) / (side - 1);
  const double plain_other = basins::distance_to_other_mode(plain.map, solution.u, solution.v, home);
  const double damped_other = basins::distance_to_other_mode(damped.map, solution.u, solution.v, home);
  const double plain_fail = basins::distance_to_failure(plain.map, solution.u, solution.v);
  const double damped_fail = basins::distance_to_failure(damped.map, solution.u, solution.v);
  const auto cell = [](double x) { return std::isfinite(x) ? fmt::format("{:.6g}", x) : std::string("none"); };
  Table distances({"measure", "plain", "damped"});
  distances.add_row({"seed's estimates from the solution (rad)", cell(estimate_distance), cell(estimate_distance)});
  distances.add_row({"nearest start on another branch (rad)", cell(plain_other), cell(damped_other)});
  distances.add_row({"nearest failing start (rad)", cell(plain_fail), cell(damped_fail)});
  distances.add_row({"grid step (rad)", cell(step), cell(step)});
  distances.add_row({"starts reaching the seed's branch", std::to_string(p.per_mode[home]), std::to_string(d.per_mode[home])});
  distances.add_row({"failing starts", std::to_string(failed(p)), std::to_string(failed(d))});
  distances.add_row({"starts", std::to_string(p.total), std::to_string(d.total)});
  session.show(distances, "jansen-distances");
  session.say(basins::seed_position_sentence(estimate_distance, estimate_home, basins::JansenModes::label(home)));
  session.say(basins::stray_sentence("Plain Newton", plain_other, plain_fail, step));
  session.say(basins::stray_sentence("Damped Newton", damped_other, damped_fail, step));
  session.say(basins::damping_sentence(p.per_mode[home], d.per_mode[home], p.total, failed(p), failed(d)));
  chart(session, "step3-jansen-plain", plain, fmt::format("Jansen leg at 1.57 rad: plain Newton from {} x {} starts", side, side),
        "The Jansen leg's branches reached by plain Newton on the theta1-theta7 slice");
  chart(session, "step3-jansen-damped", damped, fmt::format("Jansen leg at 1.57 rad: damped Newton from {} x {} starts", side, side),
        "The same slice with damped Newton");
}

}  // namespace

int run_basins_lab(LabSession& session) {
  fractal_step(session);
  four_bar_step(session);
  jansen_step(session);
  return exit_success;
}

}  // namespace numlab::cli
