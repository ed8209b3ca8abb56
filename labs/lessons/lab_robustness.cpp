// Lab `robustness`: every MINPACK test case run by every solver (bench/robustness_runs.hpp), read
// through the success table and the profiles: where plain Newton fails and why, what damping buys,
// what GSL's hybrid (dogleg) types buy, and whether damped Newton solves as many cases as GSL's
// best type. Every sentence is built from the rows of the table printed just before it.

#include <fmt/format.h>

#include <algorithm>
#include <map>

#include "bench/bench_robustness.hpp"
#include "bench/robustness_runs.hpp"
#include "lessons/lab.hpp"
#include "lessons/lab_sentences.hpp"

namespace numlab::cli {

namespace {

// GSL's types that take a dogleg step inside a trust region (Powell's hybrid method).
bool dogleg_type(const std::string& solver) { return solver.starts_with("gsl-hybrid"); }

std::string label(const RobustnessResults& results, int case_index) {
  return nonlinear::case_label(results.cases.at(case_index));
}

// "a: status (||f||_inf = r); b: ..." or "none".
std::string failure_list(const RobustnessResults& results, const std::vector<const RobustnessRun*>& runs) {
  if (runs.empty()) return "none";
  std::string list;
  for (const RobustnessRun* run : runs) {
    list += fmt::format("{}{}: {} (||f||_inf = {})", list.empty() ? "" : "; ", label(results, run->case_index),
                        to_string(run->status), scientific(run->residual_norm));
  }
  return list;
}

// The runs of `solver` that did not solve their case.
std::vector<const RobustnessRun*> failures_of(const RobustnessResults& results, const std::string& solver) {
  std::vector<const RobustnessRun*> failed;
  for (const RobustnessRun& run : results.runs) {
    if (run.solver == solver && run.applies && !run.solved) failed.push_back(&run);
  }
  return failed;
}

// The runs of `solver` on the cases `other` solves and `solver` does not.
std::vector<const RobustnessRun*> solved_only_by(const RobustnessResults& results, const std::string& other,
                                                 const std::string& solver) {
  std::vector<const RobustnessRun*> runs;
  for (std::size_t c = 0; c < results.cases.size(); ++c) {
    const RobustnessRun& mine = results.run(static_cast<int>(c), solver);
    if (results.run(static_cast<int>(c), other).solved && !mine.solved) runs.push_back(&mine);
  }
  return runs;
}

// The failed runs with the solver's own closing line: why each stopped.
Table failure_table(const RobustnessResults& results, const std::vector<const RobustnessRun*>& runs) {
  Table table({"case", "status", "||f||_inf", "iterations", "why (the solver's termination line)"});
  for (const RobustnessRun* run : runs) {
    table.add_row({label(results, run->case_index), std::string(to_string(run->status)), scientific(run->residual_norm),
                   std::to_string(run->iterations), run->termination});
  }
  return table;
}

// The median (the upper one of an even count, as the bench's tables take it).
double median_of(std::vector<double> values) {
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}

std::string best_of(const RobustnessResults& results, const std::vector<std::string>& solvers) {
  return *std::max_element(solvers.begin(), solvers.end(), [&](const std::string& a, const std::string& b) {
    return solved_count(results, a) < solved_count(results, b);
  });
}

// Two solvers case by case, where one solves and the other does not.
Table difference_table(const RobustnessResults& results, const std::string& first, const std::string& second) {
  Table table({"case", first, second});
  for (std::size_t c = 0; c < results.cases.size(); ++c) {
    const RobustnessRun& a = results.run(static_cast<int>(c), first);
    const RobustnessRun& b = results.run(static_cast<int>(c), second);
    if (a.solved != b.solved) table.add_row({label(results, static_cast<int>(c)), outcome_text(a), outcome_text(b)});
  }
  return table;
}

void show_test_set(LabSession& session, const RobustnessResults& results) {
  if (!session.begin_step("The test set, the solvers, and what counts as solved",
                          "The cases are those of MINPACK's test driver for hybrj (Moré, Garbow & Hillstrom): each problem "
                          "at the driver's size, from its standard start x0 and, where the driver uses them, from 10 x0 "
                          "and 100 x0. Every solver runs every case with the same budget; a run counts as solved only "
                          "when the residual at the point it returns is small, whatever the solver itself reported.")) return;
  std::map<std::string, int> problems;
  for (const auto& test_case : results.cases) ++problems[test_case.problem];
  std::string definition = solved_definition();
  definition.front() = 'S';
  session.say(fmt::format("{} cases from {} problems; {} solvers. {}.", results.cases.size(), problems.size(),
                          results.solvers.size(), definition));
  session.show(success_counts_table(results), "counts");
}

void show_plain_failures(LabSession& session, const RobustnessResults& results) {
  const std::string plain = "newton-gepp";
  if (!session.begin_step("Where plain Newton fails, and why",
                          "Plain Newton takes the full step J dx = -f every time. Each failure below is named by the status "
                          "the solver stopped with: max_iterations (the budget ran out while the iterates wandered), "
                          "no_progress (the steps became negligible away from a root), singular (J could not be "
                          "solved), diverged or non_finite (the iterates ran away).")) return;
  const auto failed = failures_of(results, plain);
  session.show(failure_table(results, failed), "plain-failures");
  session.say(fmt::format("{} solves {} cases. It fails on {}: {}.", plain,
                          count_of(solved_count(results, plain), static_cast<int>(results.cases.size())),
                          failed.size(), failure_list(results, failed)));
}

void show_damping(LabSession& session, const RobustnessResults& results) {
  const std::string plain = "newton-gepp";
  const std::string damped = "damped-gepp";
  if (!session.begin_step("What damping buys",
                          "Damped Newton halves the step until ||f||_2^2 decreases enough (Armijo). That keeps the "
                          "iterates from jumping far away, but it also makes them stop where ||f||_2^2 has a local "
                          "minimum that is not a root: there the line search finds no decrease (no_progress), or the "
                          "steps stay tiny until the budget ends. The table lists the cases where the two differ.")) return;
  session.show(difference_table(results, plain, damped), "damping");
  const auto rescued = solved_only_by(results, damped, plain);
  const auto lost = solved_only_by(results, plain, damped);
  const int total = static_cast<int>(results.cases.size());
  session.say(fmt::format("{} solves {} cases, {} {}. Damping rescues {} case(s) plain Newton fails ({}) and loses "
                          "{} case(s) plain Newton solves ({}).",
                          damped, count_of(solved_count(results, damped), total), plain,
                          count_of(solved_count(results, plain), total), rescued.size(),
                          failure_list(results, rescued), lost.size(), failure_list(results, lost)));
}

void show_dogleg(LabSession& session, const RobustnessResults& results) {
  if (!session.begin_step("What the hybrid (dogleg) methods buy",
                          "GSL's hybrid types (hybrids, hybrid, hybridsj, hybridj) are MINPACK's Powell hybrid method: "
                          "inside a trust region they step along a dogleg between the Newton step and the steepest-"
                          "descent step, and shrink the region when ||f|| does not decrease. Its other types take "
                          "Newton (newton, dnewton), globally convergent Newton (gnewton) or Broyden steps.")) return;
  Table table({"GSL type", "family", "solved", "cases"});
  std::vector<std::string> dogleg, other;
  for (const std::string& solver : results.solvers) {
    if (!solver.starts_with("gsl-")) continue;
    (dogleg_type(solver) ? dogleg : other).push_back(solver);
    table.add_row({solver, dogleg_type(solver) ? "dogleg" : "newton-like", std::to_string(solved_count(results, solver)),
                   std::to_string(results.cases.size())});
  }
  session.show(table, "gsl-types");
  const int total = static_cast<int>(results.cases.size());
  const std::string best_dogleg = best_of(results, dogleg);
  const std::string best_other = best_of(results, other);
  session.say(fmt::format("The best dogleg type, {}, solves {} cases; the best newton-like type, {}, solves {}.",
                          best_dogleg, count_of(solved_count(results, best_dogleg), total), best_other,
                          count_of(solved_count(results, best_other), total)));
  session.show(difference_table(results, "damped-gepp", best_dogleg), "dogleg-vs-damped");
  const auto dogleg_only = solved_only_by(results, best_dogleg, "damped-gepp");
  const auto damped_only = solved_only_by(results, "damped-gepp", best_dogleg);
  session.say(fmt::format("{} solves {} case(s) damped-gepp fails ({}); damped-gepp solves {} case(s) {} fails.",
                          best_dogleg, dogleg_only.size(), failure_list(results, dogleg_only), damped_only.size(),
                          best_dogleg));

  // The price: evaluations (a Jacobian counted as n) where both solve.
  Table cost({"case", "damped-gepp evaluations", best_dogleg + " evaluations"});
  std::vector<double> damped_evaluations, dogleg_evaluations;
  for (std::size_t c = 0; c < results.cases.size(); ++c) {
    const RobustnessRun& a = results.run(static_cast<int>(c), "damped-gepp");
    const RobustnessRun& b = results.run(static_cast<int>(c), best_dogleg);
    if (!a.solved || !b.solved) continue;
    damped_evaluations.push_back(a.evaluations);
    dogleg_evaluations.push_back(b.evaluations);
    cost.add_row({label(results, static_cast<int>(c)), fmt::format("{:g}", a.evaluations), fmt::format("{:g}", b.evaluations)});
  }
  session.show(cost, "dogleg-cost");
  if (!damped_evaluations.empty()) {
    session.say(fmt::format("On the {} cases both solve, {} needs a median of {:g} function evaluations (a Jacobian "
                            "counted as n) and damped-gepp {:g}.",
                            damped_evaluations.size(), best_dogleg, median_of(dogleg_evaluations),
                            median_of(damped_evaluations)));
  }
}

void show_goal(LabSession& session, const RobustnessResults& results) {
  if (!session.begin_step("Does damped Newton solve as many cases as GSL's best type?",
                          "The hand-written damped Newton with each inner solver that runs on every case, against the "
                          "GSL type that solves the most cases.")) return;
  std::vector<std::string> damped, gsl;
  for (const std::string& solver : profiled_solvers(results)) {
    if (solver.starts_with("damped-")) damped.push_back(solver);
    if (solver.starts_with("gsl-")) gsl.push_back(solver);
  }
  const std::string best_damped = best_of(results, damped);
  const std::string best_gsl = best_of(results, gsl);
  const int total = static_cast<int>(results.cases.size());
  const int mine = solved_count(results, best_damped);
  const int theirs = solved_count(results, best_gsl);
  session.show(difference_table(results, best_damped, best_gsl), "best-gsl");
  const auto missing = solved_only_by(results, best_gsl, best_damped);
  if (!missing.empty()) session.show(failure_table(results, missing), "best-gsl-why");
  if (mine >= theirs) {
    session.say(fmt::format("Yes: {} solves {} cases, GSL's best type {} solves {}.", best_damped, count_of(mine, total),
                            best_gsl, count_of(theirs, total)));
  } else {
    session.say(fmt::format("No: {} solves {} cases, GSL's best type {} solves {}. The cases {} solves and {} does not, "
                            "with the status damped Newton stopped with: {}.",
                            best_damped, count_of(mine, total), best_gsl, count_of(theirs, total), best_gsl,
                            best_damped, failure_list(results, missing)));
  }
  const int dogleg = solved_count(results, "dogleg");
  session.say(fmt::format("The hand-written trust-region dogleg Newton (dogleg, numlab/nonlinear/dogleg.hpp) solves {} "
                          "cases, {} {}. It fails on {}.",
                          count_of(dogleg, total), dogleg >= theirs ? "at least as many as" : "fewer than", best_gsl,
                          failure_list(results, failures_of(results, "dogleg"))));
}

void show_profiles(LabSession& session, const RobustnessResults& results) {
  if (!session.begin_step("The profiles",
                          "A performance profile (Dolan & Moré) plots, for each solver, the fraction of cases it solves "
                          "within tau times the cost of the cheapest solver on that case: the left end is how often it is "
                          "the cheapest, the right end how often it solves at all. A data profile (Moré & Wild) plots "
                          "the fraction solved within kappa (n+1) function evaluations, a Jacobian counted as n. Solvers "
                          "that do not run on every case (inverse2x2, sequential) are in the table, not the profiles.")) return;
  const RobustnessFiles files = robustness_files(session.folder());
  write_robustness_files(files, results);
  session.figure(files.time_chart.chart, "performance profile on time");
  session.figure(files.evaluation_chart.chart, "performance profile on function evaluations");
  session.figure(files.data_chart.chart, "data profile: solved within kappa (n+1) evaluations");
  session.say("The success table, case by case, is in " + files.text + " (and " + files.csv + ").");
}

}  // namespace

int run_robustness_lab(LabSession& session) {
  // One timed run per case and solver: the lab reads the profiles' shape; `numlab bench robustness`
  // takes the medians of five. (Three repeats cost the lab 19 s here, and past 6 min under ASan.)
  const RobustnessResults results = run_robustness(nonlinear::minpack_cases(), 1);
  show_test_set(session, results);
  show_plain_failures(session, results);
  show_damping(session, results);
  show_dogleg(session, results);
  show_goal(session, results);
  show_profiles(session, results);
  return 0;
}

}  // namespace numlab::cli
