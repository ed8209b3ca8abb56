// Lab `inverse2x2`: the 2x2 closed form of seed 003, a scale-aware singularity test, and a nearly
// singular 2x2 against GSL.

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "lessons/lab.hpp"
#include "lessons/lab_sentences.hpp"
#include "methods/linear_methods.hpp"
#include "numlab/linalg/inverse2x2.hpp"
#include "numlab/linalg/measures.hpp"

namespace numlab::cli {

namespace {

// Step 1: the 2x2 closed form on A = [4 3; 6 3].
void show_the_closed_form(LabSession& session, const Eigen::Matrix2d& A) {
  if (!session.begin_step("The closed form",
                          "For A = [a b; c d]: det A = ad - bc and A^-1 = (1/det A) [d -b; -c a]. Four multiplications, "
                          "one division: this is what seed 003 uses inside each 2x2 Newton loop.")) return;
  const linalg::Inverse2x2 closed = linalg::inverse2x2(A);
  session.say(fmt::format("A = [4 3; 6 3]: det = {:.6g}, A^-1 = [{:.6g} {:.6g}; {:.6g} {:.6g}], kappa_2 = {:.6g}; "
                          "||A A^-1 - I||_max = {:.2g}.",
                          closed.determinant, closed.inverse(0, 0), closed.inverse(0, 1), closed.inverse(1, 0),
                          closed.inverse(1, 1), closed.condition_number,
                          (A * closed.inverse - Eigen::Matrix2d::Identity()).cwiseAbs().maxCoeff()));
  // The same closed form solving A x = b, b = A (1, 1), traced (numlab solve linear --method inverse2x2 --trace).
  const Eigen::Vector2d b = A * Eigen::Vector2d::Ones();
  session.out() << fmt::format("  A x = b with b = A (1, 1) = ({:g}, {:g}), traced:\n", b(0), b(1));
  ClosedFormTracer tracer(&session.out(), nullptr);
  run_linear_method("inverse2x2", A, b, {}, {nullptr, nullptr, &tracer});
  session.stepper("closed-form", "the closed form on A x = b", tracer);
}

// Step 2: a singularity test judged by the scale of A, not by |det A| alone.
void show_singular_relative_to_scale(LabSession& session, const Eigen::Matrix2d& A) {
  const Eigen::Matrix2d tiny = (Eigen::Matrix2d() << 1e-7, 0, 0, 1e-7).finished();
  const Eigen::Matrix2d parallel = (Eigen::Matrix2d() << 1e10, 1e10, 1e10, 1e10 + 2e-6).finished();
  if (!session.begin_step("Singular relative to what? The scale of A",
                          fmt::format("A test like |det A| < 1e-12 calls [1e-7 0; 0 1e-7] singular (det {:.2g}) although "
                                      "it is a perfectly conditioned multiple of I, and passes [1e10 1e10; 1e10 1e10+2e-6] "
                                      "(det {:.3g}) although its rows are parallel to within one rounding unit. For a 2x2, "
                                      "||A||_F^2 / |det A| = kappa + 1/kappa, so numlab calls A singular when |det A| <= "
                                      "eps ||A||_F^2, that is when kappa_2(A) >= 1/eps, whatever the scale.",
                                      linalg::inverse2x2(tiny).determinant, linalg::inverse2x2(parallel).determinant))) return;
  Table scale({"A", "det A", "kappa_2", "status"});
  const std::vector<std::pair<std::string, Eigen::Matrix2d>> examples = {
      {"[1e-7 0; 0 1e-7]", tiny},
      {"[1e10 1e10; 1e10 1e10+2e-6]", parallel},
      {"1e-200 * [4 3; 6 3]", 1e-200 * A},
      {"1e200 * [4 3; 6 3]", 1e200 * A},
      {"[1 2; 2 4]", (Eigen::Matrix2d() << 1, 2, 2, 4).finished()},
  };
  for (const auto& [name, matrix] : examples) {
    const linalg::Inverse2x2 result = linalg::inverse2x2(matrix);
    scale.add_row({name, scientific(result.determinant), scientific(result.condition_number),
                   std::string(to_string(result.status))});
  }
  session.show(scale, "scale");
  const linalg::Inverse2x2 small = linalg::inverse2x2(1e-200 * A), large = linalg::inverse2x2(1e200 * A);
  session.say(fmt::format("The exact determinants of the two scaled matrices are -6e-400 and -6e+400, outside the "
                          "doubles: computed, they are {:g} and {:g}. numlab therefore first scales A by a power of "
                          "two (exact) and tests the determinant of the scaled matrix; their status: {} and {}.",
                          small.determinant, large.determinant, to_string(small.status), to_string(large.status)));
}

// Each method's worst forward error (and where), and its residuals' range, over the solved rows.
struct Worst {
  double error = 0.0, kappa = 0.0;
  std::string where;
  std::vector<double> residuals;
  void add(const Eigen::VectorXd& x, const Eigen::Vector2d& exact, double residual, double d, double k) {
    if (!x.allFinite()) return;
    const double e = linalg::forward_error(x, exact);
    if (e > error || where.empty()) error = e, kappa = k, where = fmt::format("d = {:g}", d);
    residuals.push_back(residual);
  }
};

// The nearly singular 2x2 solved by the closed form and GSL LU for shrinking d, each method's
// worst row kept.
Table nearly_singular_table(Worst& closed_worst, Worst& lu_worst) {
  Table nearly({"d", "kappa_2", "closed form", "forward error", "rel. residual", "GSL LU", "forward error",
                "rel. residual"});
  for (double d : {1e-2, 1e-6, 1e-10, 1e-13, 1e-15, 1e-16}) {
    Eigen::Matrix2d M;
    M << 1, 1, 1, 1 + d;
    const Eigen::Vector2d exact(0.1, 0.7);
    const Eigen::Vector2d b = M * exact;
    const linalg::Inverse2x2 inverse = linalg::inverse2x2(M);
    const linalg::LinearResult<2> closed_form = linalg::solve2x2(M, b);
    const DynamicResult lu = run_linear_method("gsl-lu", M, b);
    auto errors = [&](const Eigen::VectorXd& x) -> std::pair<std::string, std::string> {
      if (!x.allFinite()) return {"-", "-"};
      return {scientific(linalg::forward_error(x, exact)), scientific(linalg::relative_residual(M, b, x))};
    };
    const auto [closed_error, closed_residual] = errors(closed_form.x);
    const auto [lu_error, lu_residual] = errors(lu.x);
    nearly.add_row({scientific(d), scientific(inverse.condition_number), std::string(to_string(closed_form.status)),
                    closed_error, closed_residual, std::string(to_string(lu.status)), lu_error, lu_residual});
    const Eigen::VectorXd closed_x = closed_form.x;
    if (closed_x.allFinite()) closed_worst.add(closed_x, exact, linalg::relative_residual(M, b, closed_x), d, inverse.condition_number);
    if (lu.x.allFinite()) lu_worst.add(lu.x, exact, linalg::relative_residual(M, b, lu.x), d, inverse.condition_number);
  }
  return nearly;
}

// Step 3: where the closed form fails, a nearly singular 2x2, against GSL LU.
void show_a_nearly_singular_2x2(LabSession& session) {
  if (!session.begin_step("Where it fails: a nearly singular 2x2",
                          "A = [1 1; 1 1+d], b = A * (0.1, 0.7), rounded. As d shrinks the rows become parallel and "
                          "kappa grows like 4/d. The closed form's forward error grows like kappa * eps: it multiplies "
                          "b by the rounded entries of A^-1 (as large as 1/d) and then subtracts, so each rounding is "
                          "amplified by 1/d. At d = 1e-16, 1+d rounds to 1: exactly singular, and both methods say so.")) return;
  Worst closed_worst, lu_worst;
  const Table nearly = nearly_singular_table(closed_worst, lu_worst);
  session.show(nearly, "nearly-singular");
  const double lu_residual = *std::max_element(lu_worst.residuals.begin(), lu_worst.residuals.end());
  session.say(fmt::format("The residual columns show why they differ. GSL LU's relative residual is {} for every d: "
                          "LU with partial pivoting is backward stable. The closed form's residual {} as d shrinks: "
                          "solving through an explicit inverse is not backward stable.",
                          lu_residual == 0.0 ? "0" : fmt::format("at most {:.2g}", lu_residual),
                          trend_phrase(closed_worst.residuals)));
  session.say(digits_lost_sentence("The closed form", closed_worst.error, closed_worst.where, closed_worst.kappa) +
              " " + digits_lost_sentence("GSL LU", lu_worst.error, lu_worst.where, lu_worst.kappa) +
              " Both forward errors are bounded only by about kappa * eps; on a 2x2 inside a Newton loop, where "
              "kappa is moderate, the closed form's speed wins.");
}

// Step 4: the closed form against GEPP, GSL LU and Eigen LU on A.
void compare_with_gsl(LabSession& session, const Eigen::Matrix2d& A) {
  if (!session.begin_step("The closed form against GSL",
                          "A = [4 3; 6 3], b = A * (1, 1). Both are exact to rounding here; the closed form needs no "
                          "pivoting, workspace or loop, which is why seed 003 uses it inside every Newton iteration.")) return;
  const Eigen::Vector2d exact(1, 1);
  session.show(linear_comparison_table(A, A * exact, exact, {"inverse2x2", "gepp", "gsl-lu", "eigen-lu"}), "comparison");
}

}  // namespace

int run_inverse2x2_lab(LabSession& session) {
  Eigen::Matrix2d A;
  A << 4, 3, 6, 3;
  show_the_closed_form(session, A);
  show_singular_relative_to_scale(session, A);
  show_a_nearly_singular_2x2(session);
  compare_with_gsl(session, A);
  return 0;
}

}  // namespace numlab::cli
