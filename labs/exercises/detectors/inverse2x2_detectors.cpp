#include "exercises/detectors/inverse2x2_detectors.hpp"

#include <cmath>
#include <fmt/format.h>
#include <limits>
#include <string>
#include <vector>

#include "exercises/detectors/explains.hpp"
#include "numlab/linalg/inverse2x2.hpp"

namespace numlab::exercises::detectors {

namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();

struct WrongForm {
  const char* cause;
  Eigen::Matrix2d value;
  const char* what;
  const char* remedy;
};

}  // namespace

std::optional<Diagnosis> diagnose_inverse2x2(const Eigen::Matrix2d& A, const InverseAnswer& answer) {
  const linalg::Inverse2x2 closed = linalg::inverse2x2(A);
  const double kappa = closed.condition_number;
  const double allowed = 10.0 * kappa * eps;
  const double det = closed.determinant;
  const double frobenius2 = A.squaredNorm();
  // The determinant as an unscaled closed form computes it, and its singular test.
  const double raw_det = A(0, 0) * A(1, 1) - A(0, 1) * A(1, 0);
  const double raw_threshold = eps * (A(0, 0) * A(0, 0) + A(0, 1) * A(0, 1) + A(1, 0) * A(1, 0) + A(1, 1) * A(1, 1));
  const bool invertible = closed.status != Status::singular;
  std::vector<Detector> detectors;
  if (answer.inverse && invertible) {
    const Eigen::Matrix2d& R = closed.inverse;
    const std::vector<WrongForm> forms = {
        {"transposed", R.transpose(), "the inverse transposed, [d -c; -b a] / det", "A^-1 = [d -b; -c a] / det"},
        {"determinant_sign", -R, "the inverse with det = b c - a d", "det = a d - b c"},
        {"no_scaling", R * det, "the adjugate [d -b; -c a] not divided by det",
         "divide the adjugate by det: A^-1 = [d -b; -c a] / det"},
        {"no_scaling", R * det * det, "the adjugate multiplied by det instead of divided",
         "divide the adjugate by det: A^-1 = [d -b; -c a] / det"},
    };
    for (const WrongForm& form : forms) {
      detectors.push_back({form.cause, Specificity::exact, [&, form]() -> std::optional<std::string> {
                             const double distance = relative_distance(*answer.inverse, form.value);
                             const double separation = relative_distance(form.value, R);
                             if (!explains(distance, separation, allowed, allowed)) return std::nullopt;
                             return fmt::format("your inverse equals {} to {} (it differs from A^-1 by {}; det = {}): {}",
                                                form.what, measured(distance), measured(separation), measured(det),
                                                form.remedy);
                           }});
    }
  }
  if (answer.singular && invertible) {
    detectors.push_back({"no_scaling", Specificity::exact, [&]() -> std::optional<std::string> {
                           if (!(std::abs(raw_det) <= raw_threshold)) return std::nullopt;
                           return fmt::format("unscaled, a d = {} and b c = {} {}: det computes as {} and eps*||A||_F^2 "
                                              "as {}, so the test calls A singular; |det A| / ||A||_F^2 = 1 / (kappa + "
                                              "1/kappa) = {} is far above eps: scale A by a power of two first (A^-1 = (A/s)^-1 / s)",
                                              measured(A(0, 0) * A(1, 1)), measured(A(0, 1) * A(1, 0)),
                                              A.cwiseAbs().maxCoeff() < 1.0 ? "underflow" : "overflow", measured(raw_det),
                                              measured(raw_threshold), measured(1.0 / (kappa + 1.0 / kappa)));
                         }});
    detectors.push_back({"absolute_singular_threshold", Specificity::family, [&]() -> std::optional<std::string> {
                           if (!(std::abs(det) < 1e-6) || !(std::abs(det) > eps * frobenius2)) return std::nullopt;
                           return fmt::format("you replied \"singular\" where |det A| = {} is small but |det A| / "
                                              "||A||_F^2 = {} is above eps = {} (kappa = {}): a fixed threshold such as "
                                              "1e-12 is not relative to A; only |det A| <= eps*||A||_F^2 means singular",
                                              measured(std::abs(det)), measured(std::abs(det) / frobenius2),
                                              measured(eps), measured(kappa));
                         }});
  }
  if (answer.inverse && !invertible) {
    detectors.push_back({"no_singular_test", Specificity::exact, [&]() -> std::optional<std::string> {
                           return fmt::format("you sent an inverse (largest entry {}) where |det A| = {} <= "
                                              "eps*||A||_F^2 = {}: the determinant is rounding noise; test |a d - b c| "
                                              "against eps*(a^2 + b^2 + c^2 + d^2) before dividing",
                                              measured(answer.inverse->cwiseAbs().maxCoeff()), measured(std::abs(det)),
                                              measured(eps * frobenius2));
                         }});
  }
  return diagnose(detectors);
}

}  // namespace numlab::exercises::detectors
