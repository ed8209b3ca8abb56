// Lab `inverse2x2`: the 2x2 closed form of seed 003, a scale-aware singularity test, and a nearly
// singular 2x2 against GSL.

#include <fmt/format.h>

#include <cmath>

#include "lab.hpp"
#include "linear_methods.hpp"
#include "numlab/linalg/inverse2x2.hpp"
#include "numlab/linalg/measures.hpp"

namespace numlab::cli {

int run_inverse2x2_lab(LabSession& session) {
  session.begin_step("The closed form",
                     "For A = [a b; c d]: det A = ad - bc and A^-1 = (1/det A) [d -b; -c a]. Four multiplications, "
                     "one division: this is what seed 003 uses inside each 2x2 Newton loop.");
  Eigen::Matrix2d A;
  A << 4, 3, 6, 3;
  const linalg::Inverse2x2 closed = linalg::inverse2x2(A);
  session.say(fmt::format("A = [4 3; 6 3]: det = {:.6g}, A^-1 = [{:.6g} {:.6g}; {:.6g} {:.6g}], kappa_2 = {:.6g}; "
                          "||A A^-1 - I||_max = {:.2g}.",
                          closed.determinant, closed.inverse(0, 0), closed.inverse(0, 1), closed.inverse(1, 0),
                          closed.inverse(1, 1), closed.condition_number,
                          (A * closed.inverse - Eigen::Matrix2d::Identity()).cwiseAbs().maxCoeff()));

  session.begin_step("Singular relative to what? The scale of A",
                     "A test like |det A| < 1e-12 calls [1e-7 0; 0 1e-7] singular (det 1e-14) although it is a "
                     "perfectly conditioned multiple of I, and misses [1e8 1e8; 1e8 1e8+1] (det 1e8). For a 2x2, "
                     "||A||_F^2 / |det A| = kappa + 1/kappa, so numlab calls A singular when |det A| <= eps ||A||_F^2, "
                     "that is when kappa_2(A) >= 1/eps, whatever the scale.");
  Table scale({"A", "det A", "kappa_2", "status"});
  const std::vector<std::pair<std::string, Eigen::Matrix2d>> examples = {
      {"[1e-7 0; 0 1e-7]", (Eigen::Matrix2d() << 1e-7, 0, 0, 1e-7).finished()},
      {"[1e8 1e8; 1e8 1e8+1]", (Eigen::Matrix2d() << 1e8, 1e8, 1e8, 1e8 + 1).finished()},
      {"1e-200 * [4 3; 6 3]", 1e-200 * A},
      {"1e200 * [4 3; 6 3]", 1e200 * A},
      {"[1 2; 2 4]", (Eigen::Matrix2d() << 1, 2, 2, 4).finished()},
  };
  for (const auto& [name, matrix] : examples) {
    const linalg::Inverse2x2 result = linalg::inverse2x2(matrix);
    scale.add_row({name, scientific(result.determinant), scientific(result.condition_number),
                   std::string(to_string(result.status))});
  }
  session.show(scale);

  session.begin_step("Where it fails: a nearly singular 2x2",
                     "A = [1 1; 1 1+d], b = A * (1, 1). As d shrinks the two rows become parallel, kappa grows like "
                     "4/d, and the forward error grows like kappa * eps for the closed form and for GSL LU alike: "
                     "no formula can recover digits the data do not hold. At d = 1e-16, 1+d rounds to 1: exactly "
                     "singular.");
  Table nearly({"d", "det A", "kappa_2", "closed form status", "forward error", "GSL LU status", "forward error"});
  for (double d : {1e-2, 1e-6, 1e-10, 1e-13, 1e-15, 1e-16}) {
    Eigen::Matrix2d M;
    M << 1, 1, 1, 1 + d;
    const Eigen::Vector2d exact(1, 1);
    const Eigen::Vector2d b = M * exact;
    const linalg::Inverse2x2 inverse = linalg::inverse2x2(M);
    const linalg::LinearResult<2> closed_form = linalg::solve2x2(M, b);
    const DynamicResult lu = run_linear_method("gsl-lu", M, b);
    const bool closed_ok = closed_form.x.allFinite();
    const bool lu_ok = lu.x.allFinite();
    nearly.add_row({scientific(d), scientific(inverse.determinant), scientific(inverse.condition_number),
                    std::string(to_string(closed_form.status)),
                    closed_ok ? scientific(linalg::forward_error(closed_form.x, exact)) : "-",
                    std::string(to_string(lu.status)), lu_ok ? scientific(linalg::forward_error(lu.x, exact)) : "-"});
  }
  session.show(nearly);

  session.begin_step("The closed form against GSL",
                     "A = [4 3; 6 3], b = A * (1, 1). Both are exact to rounding here; the closed form needs no "
                     "pivoting, workspace or loop, which is why seed 003 uses it inside every Newton iteration.");
  const Eigen::Vector2d exact(1, 1);
  session.show(linear_comparison_table(A, A * exact, exact, {"inverse2x2", "gepp", "gsl-lu", "eigen-lu"}));
  return 0;
}

}  // namespace numlab::cli
