#pragma once
// Sentences the labs build from the numbers they have just printed, so that a lab's text can
// never contradict its own table. Each function takes the numbers of one table (or one run) and
// says what they show; tests/labs checks every sentence against the lab's printed rows.

#include <string>
#include <vector>

namespace numlab::cli {

// "3 of 6", "all 6" or "none of the 6".
std::string count_of(int count, int total);

// How time t compares with time `other`: "2.07x faster than", "1.46x slower than", or "as fast as"
// (within 1%). The ratio is printed with two decimals.
std::string speed_ratio_phrase(double time, double other_time);

// One solver's cost over the same work: its name, the time, and the Newton iterations summed.
struct SolverCost {
  std::string name;
  double time_s;
  int iterations;
};

// Sequential against full Newton on the Jansen leg: which is faster and by how much, and why
// (iterations against the cost of each iteration: a 2x2 block in closed form against the whole
// n x n Jacobian evaluated and eliminated).
std::string block_newton_sentence(const SolverCost& sequential, const SolverCost& full, int unknowns);
// Two implementations of the same method (e.g. full Newton and GSL's newton): the speed ratio,
// and whether it comes from the iteration count or from the cost of each iteration.
std::string same_method_sentence(const SolverCost& mine, const SolverCost& library);
// Newton against the closed form: the ratio, and the iterations per pose the warm start leaves.
std::string closed_form_sentence(const SolverCost& newton, const SolverCost& closed_form, int poses);

// One row of a conditioning table: size, condition number, and whether the solver said singular.
struct ConditionRow {
  int n;
  double kappa;
  bool singular;
};
// Where kappa first exceeds 1/eps and where the solver first says singular, as the rows show.
std::string condition_limit_sentence(const std::vector<ConditionRow>& rows);

// GEPP's kept factors checked: max|PA - LU| relative to max|a_ij|, against the n * eps * growth that
// rounding allows ("exactly" at 0, "to rounding" within it, "only to" beyond it).
std::string lu_factors_sentence(double max_difference, double matrix_max, int n, double growth);

// Correct digits lost to a relative forward error, against the unit roundoff: log10(error / eps),
// at least 0.
double digits_lost(double forward_error);
// A method's worst forward error over a table (at the parameter `where`) in digits lost, and
// against the kappa * eps bound there.
std::string digits_lost_sentence(const std::string& method, double worst_error, const std::string& where,
                                 double kappa);

// One pose of seed 003's method: the angle, and how one loop ended there.
struct LoopOutcome {
  double theta_deg;
  bool stopped;    // its test passed
  int iterations;
  double residual;  // max(|f_i|, |f_j|) of that loop at the end
};
// Where a loop ran out of iterations and where it stopped, and whether each stop is at a root
// (max(|f_i|, |f_j|) <= 1e-2, the labs' verdict).
std::string loop_stops_sentence(int loop, const std::vector<LoopOutcome>& outcomes, int iteration_limit);

// How a sequence changes from each entry to the next: "falls at every step", or how many rises.
std::string trend_phrase(const std::vector<double>& values);

}  // namespace numlab::cli
