// Lab `seidel`: Gauss-Seidel sweeps, divergence on the plain system, convergence on the normal
// equations at a price set by kappa(A)^2, and a comparison with GSL.

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "lessons/lab.hpp"
#include "lessons/lab_sentences.hpp"
#include "methods/linear_methods.hpp"
#include "numlab/linalg/measures.hpp"
#include "numlab/linalg/matrix_generators.hpp"
#include "output/trace_printers.hpp"

namespace numlab::cli {

namespace {

// Runs `method` and prints its sweep table: every row when short, else the first and last rows.
DynamicResult traced_sweeps(LabSession& session, const std::string& method, const Eigen::MatrixXd& A,
                            const Eigen::VectorXd& b, int max_sweeps) {
  constexpr std::size_t first_rows = 12, last_rows = 4;
  SweepTracer tracer(nullptr, nullptr);  // collects the rows
  LinearSettings settings;
  settings.max_iterations = max_sweeps;
  const DynamicResult result = run_linear_method(method, A, b, settings, {nullptr, &tracer});
  const auto& rows = tracer.records();
  session.out() << fmt::format("  {:>6}  {:>12}  {:>16}\n", "sweep", "||dx||_inf", "||b - A x||_inf");
  for (std::size_t k = 0; k < rows.size(); ++k) {
    if (rows.size() > first_rows + last_rows && k == first_rows) {
      session.out() << fmt::format("  {:>6}  ({} more sweeps)\n", "...", rows.size() - first_rows - last_rows);
      k = rows.size() - last_rows;
    }
    session.out() << fmt::format("  {:>6}  {:>12.4e}  {:>16.4e}\n", rows[k]["sweep"].get<int>(),
                                 rows[k]["step_inf"].get<double>(), rows[k]["residual_inf"].get<double>());
  }
  session.stepper("sweeps", method + "'s sweeps", tracer);
  session.say(fmt::format("{}: {} after {} sweeps; ||b - A x||_inf = {:.3g}.", method, to_string(result.status),
                          result.iterations, result.residual_norm));
  return result;
}

}  // namespace

int run_seidel_lab(LabSession& session) {
  if (!session.begin_step("One sweep at a time",
                          "Gauss-Seidel solves equation i for x_i using the newest values of the other unknowns, for "
                          "i = 1..n: one sweep. It stops when the largest change in a sweep, |x_k - x_(k-1)|, is below "
                          "the tolerance (1e-9, seed 001's default). Seed 001 compared the signed change, so any "
                          "component that went down passed the test: numlab takes the absolute value. Each row shows "
                          "the change and the residual of the ORIGINAL system A x = b. Here A is a 5x5 diagonally "
                          "dominant matrix, swept directly (plain).")) return {};
  const linalg::GeneratedSystem dominant = linalg::generate_system("diag-dominant", 5);
  traced_sweeps(session, "gauss-seidel-plain", dominant.A, dominant.b, 100);

  if (!session.begin_step("Where it fails: A = [[1,2,4],[2,1,2],[4,2,1]]",
                          "This matrix is not diagonally dominant. Swept directly, each sweep multiplies the error by "
                          "the spectral radius of the Gauss-Seidel iteration matrix, which exceeds 1 here: the changes "
                          "grow until numlab stops with 'diverged' (when the change has grown 1e8-fold over the first "
                          "sweep's).")) return {};
  const linalg::GeneratedSystem diverging = linalg::generate_system("gs-diverge", 3);
  traced_sweeps(session, "gauss-seidel-plain", diverging.A, diverging.b, 100);
  session.say("The same system through the normal equations A^T A x = A^T b, as seed 001 does: A^T A is "
              "symmetric positive definite, and Gauss-Seidel always converges on such a matrix.");
  const DynamicResult normal = traced_sweeps(session, "gauss-seidel", diverging.A, diverging.b, 1000);
  session.say(fmt::format("A small step is not a small error: the last step was {:.2g}, but the error is {:.2g}. "
                          "When each sweep shrinks the error only slightly, the error is many steps long.",
                          normal.step_norm, linalg::forward_error(normal.x, diverging.exact_solution)));

  if (!session.begin_step("The price: sweeps grow with kappa(A)^2",
                          "kappa(A^T A) = kappa(A)^2, and the convergence rate of Gauss-Seidel on a symmetric positive "
                          "definite matrix degrades with its condition number. Each A below is 8x8, U diag(1 ... "
                          "1/kappa) V^T with random orthogonal U and V, so kappa_2(A) is exactly the value shown.")) return {};
  Table table({"kappa(A)", "kappa^2", "sweeps (normal equations)", "sweeps / kappa^2", "forward error",
               "plain Gauss-Seidel"});
  std::vector<double> per_kappa2;
  double fewest_growth = 1e300, most_growth = 0.0;
  int previous = 0, diverged = 0, rows = 0;
  for (double kappa : {2.0, 4.0, 8.0, 16.0, 32.0, 64.0}) {
    const Eigen::MatrixXd A = linalg::matrix_with_condition(8, kappa, 7);
    const Eigen::VectorXd exact = Eigen::VectorXd::Ones(8);
    const Eigen::VectorXd b = A * exact;
    LinearSettings settings;
    settings.max_iterations = 1000000;
    const DynamicResult normal = run_linear_method("gauss-seidel", A, b, settings);
    const DynamicResult plain = run_linear_method("gauss-seidel-plain", A, b, settings);
    table.add_row({fixed(kappa, 0), fixed(kappa * kappa, 0), std::to_string(normal.iterations),
                   fixed(normal.iterations / (kappa * kappa), 2), scientific(linalg::forward_error(normal.x, exact)),
                   fmt::format("{} ({} sweeps)", to_string(plain.status), plain.iterations)});
    per_kappa2.push_back(normal.iterations / (kappa * kappa));
    if (previous > 0) {
      fewest_growth = std::min(fewest_growth, static_cast<double>(normal.iterations) / previous);
      most_growth = std::max(most_growth, static_cast<double>(normal.iterations) / previous);
    }
    previous = normal.iterations;
    diverged += plain.status == Status::diverged ? 1 : 0;
    ++rows;
  }
  session.show(table, "sweeps-vs-kappa");
  session.say(fmt::format("Each doubling of kappa multiplies the sweeps by {:.1f} to {:.1f} (4 would be exactly "
                          "kappa^2): sweeps / kappa^2 {}. Plain Gauss-Seidel diverges on {} of these matrices, which "
                          "are not diagonally dominant.",
                          fewest_growth, most_growth, trend_phrase(per_kappa2), count_of(diverged, rows)));

  if (!session.begin_step("Gauss-Seidel against GSL",
                          "A 100x100 diagonally dominant system (b = A * ones): plain Gauss-Seidel converges in a few "
                          "sweeps; the normal equations need more (and the O(n^3) product A^T A); the direct "
                          "solvers need no iteration at all.")) return {};
  const linalg::GeneratedSystem system = linalg::generate_system("diag-dominant", 100);
  session.show(linear_comparison_table(system.A, system.b, system.exact_solution,
                                       {"gauss-seidel", "gauss-seidel-plain", "gepp", "gsl-lu"}), "comparison");
  return 0;
}

}  // namespace numlab::cli
