#pragma once
// The student's trace beside numlab's (docs/exercises.md, "Your trace beside numlab's"): when a
// trace check fails, the check keeps both traces, step by step, and the first step where they part;
// the sentence that says how they part is made here from the numbers at that step. results.json
// carries it (a failing test's "trace"), and `exercise check --out DIR` draws it as DIR/trace.html
// (trace_page.hpp).

#include <Eigen/Core>
#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace numlab::exercises {

struct TraceComparison {
  std::string inputs;                 // the request's inputs, "random 8x8, seed 11"
  std::string step_name;              // what one step is: "column", "sweep", "iteration"
  int first_number = 0;               // the protocol's number of step 1: column 0, sweep 1, iteration 1
  std::vector<std::string> fields;    // the numbers of one step, in order: {"pivot_row", "pivot"}
  nlohmann::json yours = nlohmann::json::array();   // one object per step: each field a number (or list), or null
  nlohmann::json numlab = nlohmann::json::array();  // numlab's, the same fields
  std::size_t yours_total = 0, numlab_total = 0;    // steps in each trace (the lists may keep only the first ones)
  // Per numlab step, what it chose from (gepp: "candidates", a_ik for i = k ... n-1 as the matrix
  // stands at column k); null when the exercise has nothing more to show.
  nlohmann::json context;
  std::size_t parting = 0;            // 0-based: the first step where the traces part
  std::string parting_field;          // the field that parts there ("" when one trace has ended)
  long long parting_entry = -1;       // for a list field, its first entry that parts; -1 otherwise
  std::string sentence;               // "step 3 (column 2): you took row 2 as the pivot, numlab row 4 (|a| = 7 > 3)"
};

// At most this many steps of each trace are kept (more when the parting step lies beyond).
inline constexpr std::size_t kept_trace_steps = 2000;

// GEPP: the student's trace (the reply's "trace" as sent) against numlab's pivot rows, pivots and, per
// column k, the entries a_ik (i = k ... n-1) it chose from; `parting` as the check found it.
TraceComparison pivot_comparison(const std::string& inputs, const nlohmann::json& trace, const std::vector<int>& rows,
                                 const std::vector<double>& pivots, const std::vector<Eigen::VectorXd>& candidates,
                                 std::size_t parting);

// Gauss-Seidel: the student's trace against numlab's x and update_inf after each sweep; `allowed`
// is the check's tolerance on x at the parting sweep.
TraceComparison sweep_comparison(const std::string& inputs, const nlohmann::json& trace,
                                 const std::vector<Eigen::VectorXd>& xs, const std::vector<double>& updates,
                                 std::size_t parting, double allowed);

// Newton: the student's rows (residual_inf, step_inf) against numlab's from the same start, with
// the trace check's tolerances (linkage_checks.hpp, first_departure) and the request's tolerance.
struct NewtonTolerances {
  double relative = 0.0;        // of numlab's value
  double residual_floor = 0.0;  // rounding on residual_inf
  double step_floor = 0.0;      // rounding on step_inf
  double tolerance = 0.0;       // the request's stop test
};
TraceComparison newton_comparison(const std::string& inputs, const std::vector<double>& your_residuals,
                                  const std::vector<double>& your_steps, const std::vector<double>& residuals,
                                  const std::vector<double>& steps, std::size_t parting,
                                  const NewtonTolerances& tolerances);

// Two numbers with the fewest significant digits (3 to 17) that tell them apart: "7" and "3",
// "0.12346" and "0.12345".
std::pair<std::string, std::string> told_apart(double a, double b);

// {"inputs", "step_name", "first_number", "fields", "yours", "numlab", "yours_total", "numlab_total",
//  "context", "parting", "parting_field", "parting_entry", "sentence"}
nlohmann::ordered_json trace_json(const TraceComparison& comparison);

}  // namespace numlab::exercises
