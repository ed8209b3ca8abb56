#pragma once
// Every MINPACK test case (numlab/nonlinear/minpack_cases.hpp) run by every solver numlab has, with
// one budget for all, each run judged by one test of "solved" (below), its cost counted the same
// way for all: what `numlab bench robustness` and `numlab lab robustness` read.
//
// Solvers:
//   newton-L        hand-written full Newton, inner linear solver L (gepp, gauss-seidel, gsl-lu,
//                   eigen-lu; inverse2x2 where n = 2);
//   damped-L        the same with backtracking (Armijo on ||f||_2^2);
//   dogleg          hand-written trust-region dogleg Newton (numlab/nonlinear/dogleg.hpp);
//   sequential, sequential-damped
//                   block-by-block Newton (GEPP inside each block) where the Jacobian's sparsity
//                   splits the system into more than one block;
//   gsl-T           GSL's eight multiroot types.
//
// Solved: ||f(x)||_inf <= solved_tolerance at the x the solver returns, evaluated afresh here: not
// the solver's own status, and never a small step.
// Cost: function evaluations counted by a wrapper around the system, so that the evaluations in
// damping's line search and in GSL's finite differences count like any other; one Jacobian counts
// as n function evaluations (what a finite-difference Jacobian costs), so derivative-free and
// Jacobian methods are compared on one scale.

#include <string>
#include <vector>

#include "numlab/nonlinear/minpack_cases.hpp"
#include "numlab/status.hpp"

namespace numlab::cli {

inline constexpr double solved_tolerance = 1e-10;  // ||f(x)||_inf at the end
// Every solver's budget on a case with n unknowns: 100 (n + 1) iterations, the default limit of
// MINPACK's hybrj (maxfev). Generous for Newton, whose iteration costs n + 1 evaluations; exactly
// MINPACK's for the hybrid types, whose iteration costs about one.
constexpr int robustness_iteration_limit(int n) { return 100 * (n + 1); }

struct RobustnessRun {
  int case_index;       // into the cases run
  std::string solver;
  bool applies = true;  // false: inverse2x2 with n != 2, sequential with one block
  std::string not_applicable;  // why not, when it does not apply
  Status status = Status::running;  // the solver's own verdict
  bool solved = false;
  double residual_norm = 0.0;  // ||f(x)||_inf at the end (NaN when x is not finite)
  int iterations = 0;
  int function_evaluations = 0;
  int jacobian_evaluations = 0;
  double evaluations = 0.0;  // function_evaluations + n * jacobian_evaluations
  double time_s = 0.0;       // solved: median over the repeats; failed: the one counted run
  std::string termination;   // the solver's closing line: why it stopped, with its numbers
};

struct RobustnessResults {
  std::vector<nonlinear::MinpackCase> cases;
  std::vector<std::string> solvers;  // in the order of the tables
  std::vector<RobustnessRun> runs;   // case by case, each case's solvers in that order
  int repeats = 1;

  const RobustnessRun& run(int case_index, const std::string& solver) const;
};

// Every solver name, in table order: newton-*, damped-*, sequential*, gsl-*.
std::vector<std::string> robustness_solvers();

// Solvers that apply to every case (the ones a profile compares): all but inverse2x2 and sequential.
bool applies_everywhere(const std::string& solver);

// Runs every case with every solver; times are medians of `repeats` runs. `progress` (may be null)
// hears about each case before it runs.
RobustnessResults run_robustness(const std::vector<nonlinear::MinpackCase>& cases, int repeats,
                                 void (*progress)(const std::string&) = nullptr);

// "solved", or the status and ||f||_inf ("max_iterations 3.2e-02"), or "n/a".
std::string outcome_text(const RobustnessRun& run);

}  // namespace numlab::cli
