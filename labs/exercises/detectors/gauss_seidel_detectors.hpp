#pragma once
// The gauss-seidel exercise's detectors (docs/exercises.md, "Diagnosis"). With a trace, the first
// sweep that departs from numlab's is compared with the known wrong sweeps (Jacobi, the reverse
// order, A where A^T A was asked, A A^T, no update) computed from the student's own previous
// iterate; then whole runs with a known wrong stop rule are replayed and their status and sweep
// count compared with the student's.

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "exercises/diagnosis.hpp"

namespace numlab::exercises::detectors {

struct GaussSeidelProblem {
  Eigen::MatrixXd A;
  Eigen::VectorXd b, x0;
  double tolerance = 1e-9;
  int max_iterations = 100;
  bool normal_equations = false;
};

enum class SweptSystem { asked, plain, normal, a_at };  // a_at: A A^T x = A^T b
enum class SweepKind { gauss_seidel, jacobi, reverse, no_update };
enum class StopRule {
  stated,            // update_inf <= tolerance * max(1, |x|_inf)
  signed_change,     // max_i (x_i(new) - x_i(old)) < tolerance: no abs (seed 001)
  absolute,          // update_inf <= tolerance
  relative,          // update_inf <= tolerance * |x|_inf
  extra_sweep,       // the stated test, but max_iterations + 1 sweeps
  limit_converged,   // the stated test, but the limit reported as converged
  // The residual of the swept system M x = c (A^T A x = A^T b with normal_equations) in place of
  // the update: max_i |c - M x|, or its 2-norm, against tolerance.
  residual_inf,
  residual_two,
  // The same with the residual of A x = b itself, whichever system is swept.
  original_residual_inf,
  original_residual_two,
};

struct GaussSeidelRun {
  std::string status;
  std::vector<Eigen::VectorXd> xs;
  std::vector<double> updates;
  int sweeps() const { return static_cast<int>(xs.size()); }
};

// The run a student's code with these choices makes (the task's divergence test included).
GaussSeidelRun replay_gauss_seidel(const GaussSeidelProblem& problem, SweptSystem system, SweepKind kind,
                                   StopRule stop);

struct GaussSeidelSweep {
  Eigen::VectorXd x;
  double update_inf = 0.0;
};

struct GaussSeidelAnswer {
  std::string status;
  long long iterations = 0;
  std::optional<Eigen::VectorXd> x;
  std::optional<std::vector<GaussSeidelSweep>> trace;
};

std::optional<Diagnosis> diagnose_gauss_seidel(const GaussSeidelProblem& problem, const GaussSeidelAnswer& answer);

}  // namespace numlab::exercises::detectors
