// Lab `gauss`: Gaussian elimination with partial pivoting, step by step, where it fails, and
// against GSL.

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "lessons/lab.hpp"
#include "lessons/lab_sentences.hpp"
#include "methods/linear_methods.hpp"
#include "numlab/linalg/gauss_elimination.hpp"
#include "numlab/linalg/gsl_reference.hpp"
#include "numlab/linalg/measures.hpp"
#include "numlab/linalg/matrix_generators.hpp"
#include "output/trace_printers.hpp"

namespace numlab::cli {

namespace {

// Correct significant digits implied by a relative error: 0 to 16.
double digits_of(double relative_error) {
  return relative_error <= 1e-16 ? 16.0 : std::max(0.0, -std::log10(relative_error));
}

// The same, as the tables print it.
std::string digits(double relative_error) {
  if (std::isnan(relative_error)) return "-";
  if (relative_error <= 1e-16) return "16";
  return fmt::format("{:.1f}", digits_of(relative_error));
}

// The elimination kept its factors: P (the swaps), L (the multipliers) and U, and P A = L U checked.
void show_the_factors(LabSession& session, const Eigen::MatrixXd& A, const Eigen::VectorXd& b) {
  linalg::GaussElimination<Eigen::Dynamic> gepp;
  gepp.solve(A, b);
  const Eigen::MatrixXd L = gepp.lower(), U = gepp.upper();
  const Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> P = gepp.permutation();
  const Eigen::MatrixXd difference = (P * A - L * U).cwiseAbs();
  const int n = static_cast<int>(A.rows());
  session.say("The elimination kept its factors, P A = L U: row i of P A is row 'row of A' of A, L holds the "
              "multipliers, U the reduced matrix.");
  Table table({"i", "row of A", "l_i1", "l_i2", "l_i3", "u_i1", "u_i2", "u_i3", "max|PA - LU| in row"});
  Eigen::VectorXi rows(n);  // row i of P A is row rows(i) of A
  for (int j = 0; j < n; ++j) rows(P.indices()(j)) = j;
  for (int i = 0; i < n; ++i) {
    std::vector<std::string> cells = {std::to_string(i + 1), std::to_string(rows(i) + 1)};
    for (int j = 0; j < n; ++j) cells.push_back(fmt::format("{:.6g}", L(i, j)));
    for (int j = 0; j < n; ++j) cells.push_back(fmt::format("{:.6g}", U(i, j)));
    cells.push_back(fmt::format("{:.3g}", difference.row(i).maxCoeff()));
    table.add_row(cells);
  }
  session.show(table, "factors");
  session.say(lu_factors_sentence(difference.maxCoeff(), A.cwiseAbs().maxCoeff(), n, gepp.growth_factor()));
}

void trace_a_small_system(LabSession& session) {
  if (!session.begin_step("Elimination, one column at a time",
                          "For each column: search the column for the largest pivot, swap it onto the diagonal, and "
                          "subtract multiples of the pivot row to clear the entries below it. Then solve the "
                          "triangular system from the bottom up. The augmented matrix [A | b] is shown after every "
                          "swap and every elimination (numlab solve linear --method gepp --trace prints the same).")) return;
  Eigen::MatrixXd A(3, 3);
  A << 2, 1, -1, -3, -1, 2, -2, 1, 2;
  const Eigen::Vector3d b(8, -11, -3);
  session.out() << "  Start:\n";
  print_augmented(session.out(), A, b);
  EliminationTracer tracer(&session.out(), nullptr);
  const DynamicResult result = run_linear_method("gepp", A, b, {}, {&tracer, nullptr});
  nlohmann::ordered_json start = nlohmann::ordered_json::array();
  for (int i = 0; i < 3; ++i) start.push_back({A(i, 0), A(i, 1), A(i, 2), b(i)});
  session.stepper("gepp", "GEPP on the 3x3 system", tracer, {{"start", start}});
  session.say(fmt::format("Solution x = ({:.12g}, {:.12g}, {:.12g}), exact (2, 3, -1); growth factor {:.3g}.",
                          result.x(0), result.x(1), result.x(2), result.growth_factor));
  show_the_factors(session, A, b);
}

void show_a_tiny_pivot(LabSession& session) {
  if (!session.begin_step("Why pivot: a tiny pivot",
                          "A = [[d, 1], [1, 1]] with b = A * (1, 1). Without pivoting the first multiplier is 1/d, the "
                          "second row becomes 1 - 1/d, and the 1 in it is rounded away: x1 comes out of a difference of "
                          "nearly equal numbers divided by d. Swapping rows first keeps every multiplier at most 1. "
                          "When d is below n*eps the pivot counts as negligible and elimination without pivoting "
                          "stops with 'singular' instead of dividing by it.")) return;
  Table table({"d", "no pivot: status", "x1", "forward error", "growth", "partial pivot: x1", "forward error",
               "growth"});
  for (double d : {1e-4, 1e-8, 1e-12, 1e-14, 1e-17}) {
    Eigen::MatrixXd A(2, 2);
    A << d, 1, 1, 1;
    const Eigen::VectorXd exact = Eigen::VectorXd::Ones(2);
    const Eigen::VectorXd b = A * exact;
    const DynamicResult naive = run_linear_method("gepp-no-pivot", A, b);
    const DynamicResult pivoted = run_linear_method("gepp", A, b);
    const bool naive_ok = naive.x.allFinite();
    table.add_row({scientific(d), std::string(to_string(naive.status)), naive_ok ? fmt::format("{:.12g}", naive.x(0)) : "-",
                   naive_ok ? scientific(linalg::forward_error(naive.x, exact)) : "-", scientific(naive.growth_factor),
                   fmt::format("{:.12g}", pivoted.x(0)), scientific(linalg::forward_error(pivoted.x, exact)),
                   scientific(pivoted.growth_factor)});
  }
  session.show(table, "tiny-pivot");
}

void show_wilkinson_growth(LabSession& session) {
  if (!session.begin_step("Where partial pivoting fails: Wilkinson's growth matrix",
                          "W has 1 on the diagonal, -1 below it and 1 in the last column. No swap is ever needed, yet "
                          "every elimination doubles the last column: the growth factor max|U|/max|A| is 2^(n-1). "
                          "GEPP's backward error is bounded by about growth * eps, so once the growth passes 1/eps "
                          "(n > 53) every digit can be lost. Householder QR has no growth problem. Here b = W * ones.")) return;
  Table table({"n", "growth", "2^(n-1)", "GEPP forward error", "GEPP digits", "GSL LU digits", "GSL QR digits"});
  int first_lost = 0;  // the first n where GEPP keeps no digit (0.0 in the table)
  double lost_error = 0.0, qr_fewest = 16.0;
  for (int n : {10, 20, 30, 40, 50, 55, 60}) {
    const linalg::GeneratedSystem system = linalg::generate_system("wilkinson", n);
    const DynamicResult gepp = run_linear_method("gepp", system.A, system.b);
    const double gepp_error = linalg::forward_error(gepp.x, system.exact_solution);
    const double lu_error = linalg::forward_error(linalg::gsl_lu_solve(system.A, system.b).x, system.exact_solution);
    const double qr_error = linalg::forward_error(linalg::gsl_qr_solve(system.A, system.b).x, system.exact_solution);
    table.add_row({std::to_string(n), scientific(gepp.growth_factor), scientific(std::ldexp(1.0, n - 1)),
                   scientific(gepp_error), digits(gepp_error), digits(lu_error), digits(qr_error)});
    if (first_lost == 0 && digits_of(gepp_error) < 0.05) first_lost = n, lost_error = gepp_error;
    qr_fewest = std::min(qr_fewest, digits_of(qr_error));
  }
  session.show(table, "wilkinson-growth");
  session.say(first_lost == 0
                  ? "GEPP keeps its digits at every n above: the growth has not yet swamped them."
                  : fmt::format("From n = {} (growth {:.2g}, {} 1/eps) GEPP's forward error is {:.2g}: no "
                                "correct digit, while its status is still 'converged' because no pivot was small. "
                                "GSL QR keeps {:.1f} digits or more at every n. numlab solve linear reports the growth "
                                "factor and prints a warning for exactly this case.",
                                first_lost, std::ldexp(1.0, first_lost - 1),
                                std::ldexp(1.0, first_lost - 1) * std::numeric_limits<double>::epsilon() > 1.0
                                    ? "past" : "below",
                                lost_error, qr_fewest));
}

void show_hilbert_conditioning(LabSession& session) {
  if (!session.begin_step("Ill-conditioned is not unstable: Hilbert matrices",
                          "h_ij = 1/(i+j-1). GEPP stays backward stable (tiny relative residual), but the forward error "
                          "grows like kappa * eps: the data, not the method, limit the digits. GSL LU loses the same "
                          "digits. Once kappa exceeds 1/eps no digit is guaranteed, and when a pivot falls below "
                          "n*eps*max|a_ij| GEPP stops with 'singular'. kappa_1 is estimated from the LU factors "
                          "(Hager-Higham), never above the true value.")) return;
  std::vector<ConditionRow> limits;
  Table table({"n", "kappa_1 estimate", "kappa*eps", "GEPP status", "GEPP residual", "GEPP forward error",
               "GSL LU forward error"});
  for (int n : {4, 6, 8, 10, 12, 13}) {
    const linalg::GeneratedSystem system = linalg::generate_system("hilbert", n);
    const double kappa = linalg::condition_estimate(system.A);
    const DynamicResult gepp = run_linear_method("gepp", system.A, system.b);
    const DynamicResult lu = run_linear_method("gsl-lu", system.A, system.b);
    const bool solved = gepp.x.allFinite();
    table.add_row({std::to_string(n), scientific(kappa), scientific(kappa * std::numeric_limits<double>::epsilon()),
                   std::string(to_string(gepp.status)),
                   solved ? scientific(linalg::relative_residual(system.A, system.b, gepp.x)) : "-",
                   solved ? scientific(linalg::forward_error(gepp.x, system.exact_solution)) : "-",
                   scientific(linalg::forward_error(lu.x, system.exact_solution))});
    limits.push_back({n, kappa, gepp.status == Status::singular});
  }
  session.show(table, "hilbert");
  session.say(condition_limit_sentence(limits));
}

}  // namespace

int run_gauss_lab(LabSession& session) {
  trace_a_small_system(session);
  show_a_tiny_pivot(session);
  show_wilkinson_growth(session);
  show_hilbert_conditioning(session);

  if (!session.begin_step("Hand-written GEPP against GSL and Eigen",
                          "A random 200x200 system (entries uniform in [-1, 1], b = A * ones). All three LU "
                          "factorizations pivot the same way; Householder QR does twice LU's arithmetic (4n^3/3 "
                          "against 2n^3/3 flops) and needs no pivoting.")) return {};
  const linalg::GeneratedSystem system = linalg::generate_system("random", 200);
  session.show(linear_comparison_table(system.A, system.b, system.exact_solution, {"gepp", "gsl-lu", "gsl-qr", "eigen-lu"}), "comparison");
  return 0;
}

}  // namespace numlab::cli
