#include "lessons/linkage_cycle.hpp"

#include <optional>
#include <utility>

#include "numlab/mechanisms/linkage/linkage_fast_solver.hpp"

namespace numlab::cli {

namespace {

// The polynomial through columns next-m ... next-1 (m = min(next, 5)) at the next equal step: its
// m-th difference set to zero, x_next = sum_j (-1)^(j+1) C(m, j) x_(next-j).
void predict(const Eigen::MatrixXd& poses, int next, Eigen::VectorXd& prediction) {
  static constexpr int binomial[6][6] = {{0}, {0, 1}, {0, 2, -1}, {0, 3, -3, 1}, {0, 4, -6, 4, -1}, {0, 5, -10, 10, -5, 1}};
  const int m = next < 5 ? next : 5;
  prediction.setZero();
  for (int j = 1; j <= m; ++j) prediction += binomial[m][j] * poses.col(next - j);
}

}  // namespace

LinkageCycle solve_linkage_cycle(const mechanisms::LinkageSolver& solver, double start, double step, int poses) {
  const auto& model = solver.model();
  LinkageCycle cycle;
  cycle.q.resize(model.unknown_count(), poses);
  cycle.driver.reserve(static_cast<std::size_t>(poses));
  // The fast path where it applies (as `numlab bench jansen` solves the file), else the solver itself.
  std::optional<mechanisms::LinkageFastSolver> fast;
  if (mechanisms::LinkageFastSolver::applies(solver.options())) fast.emplace(solver);
  Eigen::VectorXd guess = solver.reference();
  for (int k = 0; k < poses; ++k) {
    const double value = start + k * step;
    if (k > 0) predict(cycle.q, k, guess);  // 1.
    const double t = model.driver_from_user(value);
    mechanisms::LinkageFastOutcome solved;  // 2., in place on guess
    if (fast) {
      solved = fast->solve(t, guess);
    } else {
      mechanisms::LinkageSolution solution = solver.solve(t, guess);
      guess = std::move(solution.q);
      solved = {solution.outcome, solution.failed_block};
    }
    cycle.iterations += solved.outcome.iterations;
    if (solved.outcome.status != Status::converged) {
      cycle.status = solved.outcome.status;
      break;
    }
    cycle.q.col(k) = guess;
    cycle.driver.push_back(value);
    ++cycle.solved;
  }
  return cycle;
}

}  // namespace numlab::cli
