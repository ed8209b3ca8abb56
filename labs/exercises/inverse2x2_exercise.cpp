// The `inverse2x2` exercise: the student's closed-form 2x2 inverse, checked against numlab's closed
// form (with its scaling and its singular test) and GSL LU's inverse (one solve per column).

#include <Eigen/Core>
#include <cmath>
#include <fmt/format.h>
#include <optional>

#include "exercises/detectors/inverse2x2_detectors.hpp"
#include "exercises/exercise_list.hpp"
#include "exercises/linear_checks.hpp"
#include "exercises/numbers.hpp"
#include "exercises/reply_fields.hpp"
#include "exercises/session.hpp"
#include "exercises/task_texts.hpp"
#include "numlab/linalg/gsl_reference.hpp"
#include "numlab/linalg/inverse2x2.hpp"

namespace numlab::exercises {

namespace {

using linear::eps;
using linear::sci;

struct Case {
  std::string label;
  Eigen::Matrix2d A;
};

Case matrix(std::string label, double a, double b, double c, double d) {
  return {std::move(label), (Eigen::Matrix2d() << a, b, c, d).finished()};
}

struct Reference {
  linalg::Inverse2x2 closed_form;
  Eigen::Matrix2d gsl;  // GSL LU's inverse, column by column
  double threshold = 0.0;  // eps * ||A||_F^2
};

Reference reference_for(const Case& item, linear::ReferenceTimes& times) {
  Reference reference;
  reference.closed_form = linalg::inverse2x2(item.A);
  reference.threshold = eps * item.A.squaredNorm();
  linalg::GslLu gsl(2);
  const Eigen::MatrixXd A = item.A;
  const auto gsl_inverse = [&] {
    Eigen::Matrix2d inverse;
    for (int j = 0; j < 2; ++j) inverse.col(j) = gsl.solve(A, Eigen::Vector2d::Unit(j)).x;
    return inverse;
  };
  reference.gsl = gsl_inverse();
  times.time("numlab closed form", [&] { linalg::inverse2x2(item.A); });
  times.time("GSL LU", [&] { gsl_inverse(); });
  return reference;
}

bool replied_singular(const nlohmann::json& reply) { return optional_status(reply) == std::optional<std::string>("singular"); }

// The most specific known mistake that explains the reply (inverse2x2_detectors.hpp).
std::optional<Diagnosis> diagnosis_for(const Case& item, const nlohmann::json& reply) {
  detectors::InverseAnswer answer;
  answer.singular = replied_singular(reply);
  try {
    if (!answer.singular) answer.inverse = matrix_field(reply, "inverse", 2, 2);
  } catch (const ReplyError&) {
  }
  return detectors::diagnose_inverse2x2(item.A, answer);
}

// The mistake that turns the closed form into `yours`.
std::string hint_for(const Eigen::Matrix2d& yours, const Eigen::Matrix2d& inverse, const Eigen::Matrix2d& A,
                     double allowed) {
  const auto close = [&](const Eigen::Matrix2d& candidate) { return linear::relative_error(yours, candidate) <= allowed; };
  const double det = A.determinant();
  if (close(-inverse)) return "determinant with the wrong sign: det = a d - b c";
  if (close(inverse.transpose())) return "inverse transposed: A^-1 = [d -b; -c a] / det";
  if (close(inverse * det)) return "not divided by the determinant: A^-1 = [d -b; -c a] / det";
  if (close(inverse * det * det)) return "multiplied by the determinant instead of dividing by it";
  return "A^-1 = [d -b; -c a] / (a d - b c)";
}

// Task 1 (and 3): the inverse to kappa*eps, for matrices numlab's closed form finds invertible.
Verdict inverts_accurately(Session& session, const std::vector<Case>& cases) {
  linear::ReferenceTimes times;
  for (const Case& item : cases) {
    const Reference reference = reference_for(item, times);
    const nlohmann::json reply = session.ask({{"A", to_json(Eigen::MatrixXd(item.A))}});
    session.expect({item.label, {{"inverse", to_json(Eigen::MatrixXd(reference.closed_form.inverse))}},
                    fmt::format("the inverse within {} (10*kappa*eps, relative, max-norm) of the closed form's above",
                                sci(10.0 * reference.closed_form.condition_number * eps))});
    if (replied_singular(reply)) {
      // |det A| / ||A||_F^2 = 1 / (kappa + 1/kappa) for a 2x2 matrix: free of A's scale.
      const double kappa = reference.closed_form.condition_number;
      return Verdict::fail(fmt::format("{}: you replied \"singular\"; |det A| / ||A||_F^2 = {} is above eps = {} "
                                       "(kappa = {}): numlab's closed form, with A scaled by a power of two, inverts it",
                                       item.label, sci(1.0 / (kappa + 1.0 / kappa)), sci(eps), sci(kappa)),
                           diagnosis_for(item, reply),
                           "only |det A| <= eps*||A||_F^2 means singular; scale A by a power of two first when a d "
                           "or b c could overflow or underflow",
                           times.medians());
    }
    const Eigen::Matrix2d yours = matrix_field(reply, "inverse", 2, 2);
    const Eigen::Matrix2d& inverse = reference.closed_form.inverse;
    const double kappa = reference.closed_form.condition_number;
    const double allowed = 10.0 * kappa * eps;
    const double error = linear::relative_error(yours, inverse);
    if (!(error <= allowed)) {
      Eigen::Index i = 0, j = 0;
      (yours - inverse).cwiseAbs().maxCoeff(&i, &j);
      return Verdict::fail(fmt::format("{}: inverse[{}][{}] = {}, the closed form gives {} ({}): inverse differs by {} "
                                       "(relative, max-norm), allowed {} (10*kappa*eps, kappa = {}); GSL LU agrees "
                                       "with the closed form to {}",
                                       item.label, i, j, digits17(yours(i, j)), digits17(inverse(i, j)), difference(yours(i, j), inverse(i, j)), sci(error),
                                       sci(allowed), sci(kappa), sci(linear::relative_error(reference.gsl, inverse))),
                           diagnosis_for(item, reply), hint_for(yours, inverse, item.A, allowed), times.medians());
    }
  }
  return Verdict::pass(times.medians());
}

// Task 2: "singular" where numlab's closed form finds |det A| <= eps*||A||_F^2.
Verdict reports_singular(Session& session, const std::vector<Case>& cases) {
  linear::ReferenceTimes times;
  for (const Case& item : cases) {
    const Reference reference = reference_for(item, times);
    const nlohmann::json reply = session.ask({{"A", to_json(Eigen::MatrixXd(item.A))}});
    session.expect({item.label, {{"status", "singular"}},
                    fmt::format("\"status\": \"singular\": |det A| = {} <= eps*||A||_F^2 = {}",
                                sci(std::abs(reference.closed_form.determinant)), sci(reference.threshold))});
    if (!replied_singular(reply)) {
      return Verdict::fail(fmt::format("{}: your reply has no \"status\": \"singular\"; |det A| = {} <= "
                                       "eps*||A||_F^2 = {} (kappa_2 >= 1/eps)",
                                       item.label, sci(std::abs(reference.closed_form.determinant)),
                                       sci(reference.threshold)),
                           diagnosis_for(item, reply),
                           "missing singular test: compare |a d - b c| with eps*(a^2 + b^2 + c^2 + d^2) before "
                           "dividing by the determinant",
                           times.medians());
    }
  }
  return Verdict::pass(times.medians());
}

// A variant's well-conditioned 2x2 matrix: entries in [-9.9, 9.9] with one decimal, kappa_2 <= 50.
Case drawn_matrix(Variant::Stream& stream) {
  for (;;) {
    double e[4];
    for (double& entry : e) entry = std::round(stream.uniform(-99.0, 99.0)) / 10.0;
    const Case item = matrix(fmt::format("[[{:g}, {:g}], [{:g}, {:g}]]", e[0], e[1], e[2], e[3]), e[0], e[1], e[2], e[3]);
    if (item.A.determinant() != 0.0 && linalg::inverse2x2(item.A).condition_number <= 50.0) return item;
  }
}

// A variant's exactly singular 2x2 matrix: [[a, b], [k a, k b]] with small whole numbers (det is 0
// exactly in doubles).
Case drawn_singular(Variant::Stream& stream) {
  const auto whole = [&stream](double low, double high) { return std::floor(stream.uniform(low, high + 1.0)); };
  const double a = whole(1, 9), b = whole(-9, 9), k = whole(2, 5) * (stream.uniform(0, 1) < 0.5 ? -1.0 : 1.0);
  return matrix(fmt::format("[[{:g}, {:g}], [{:g}, {:g}]]", a, b, k * a, k * b), a, b, k * a, k * b);
}

std::vector<Case> well_conditioned(const Variant& variant) {
  if (!variant.active()) {
    return {matrix("[[4, 7], [2, 6]]", 4, 7, 2, 6), matrix("[[0, 1], [1, 0]]", 0, 1, 1, 0),
            matrix("[[-3, 5], [2, -1]]", -3, 5, 2, -1), matrix("[[0.3, -1.7], [2.5, 0.9]]", 0.3, -1.7, 2.5, 0.9)};
  }
  Variant::Stream stream = variant.stream(1);
  std::vector<Case> cases;
  for (int k = 0; k < 4; ++k) cases.push_back(drawn_matrix(stream));
  return cases;
}

std::vector<Case> exactly_singular(const Variant& variant) {
  if (!variant.active()) return {matrix("[[1, 2], [2, 4]]", 1, 2, 2, 4), matrix("[[0, 0], [0, 0]]", 0, 0, 0, 0)};
  Variant::Stream stream = variant.stream(3);
  return {drawn_singular(stream), matrix("[[0, 0], [0, 0]]", 0, 0, 0, 0)};
}

// 1e-170 M and 1e170 M: M = [[4, 7], [2, 6]], or a variant's well-conditioned matrix.
std::vector<Case> scaled(const Variant& variant) {
  if (!variant.active()) {
    return {matrix("1e-170 [[4, 7], [2, 6]]", 4e-170, 7e-170, 2e-170, 6e-170),
            matrix("1e170 [[4, 7], [2, 6]]", 4e170, 7e170, 2e170, 6e170)};
  }
  Variant::Stream stream = variant.stream(5);
  const Case m = drawn_matrix(stream);
  std::vector<Case> cases;
  for (const double s : {1e-170, 1e170}) {
    cases.push_back({fmt::format("{:g} {}", s, m.label), (m.A * s).eval()});
  }
  return cases;
}

// With a variant, the well-conditioned, the exactly singular and the scaled matrices are drawn from
// it; the hand-made edge cases (badly scaled, singular to working precision) are the same for all.
std::vector<Check> inverse2x2_battery(const Variant& variant) {
  return {
      {"the inverse of well-conditioned 2x2 matrices matches the closed form and GSL LU to 10*kappa*eps", 1,
       [cases = well_conditioned(variant)](Session& s) { return inverts_accurately(s, cases); }},
      {"the inverse of badly scaled and nearly singular 2x2 matrices is accurate to 10*kappa*eps", 1,
       [](Session& s) {
         return inverts_accurately(s, {matrix("[[1e-8, 1], [1, 1]]", 1e-8, 1, 1, 1),
                                       matrix("[[1e5, 3], [2e-3, 7e-5]]", 1e5, 3, 2e-3, 7e-5),
                                       matrix("[[1, 2], [0.5, 1 + 2^-40]] (kappa ~ 7e12)", 1, 2, 0.5,
                                              1 + 0x1p-40)});
       }},
      {variant.active() ? "exactly singular 2x2 matrices (one row a multiple of the other; [[0, 0], [0, 0]]) are "
                          "reported as singular"
                        : "exactly singular 2x2 matrices ([[1, 2], [2, 4]], [[0, 0], [0, 0]]) are reported as singular",
       2,
       [cases = exactly_singular(variant)](Session& s) { return reports_singular(s, cases); }},
      {"a 2x2 matrix singular to working precision (|det A| <= eps*||A||_F^2) is reported as singular", 2,
       [](Session& s) {
         return reports_singular(s, {matrix("[[1, 2], [0.5, 1 + 2^-51]]", 1, 2, 0.5, 1 + 0x1p-51)});
       }},
      {"the inverse of a 2x2 matrix scaled by 1e-170 or 1e170 is accurate (a d under/overflows unless A is scaled)",
       3, [cases = scaled(variant)](Session& s) { return inverts_accurately(s, cases); }},
  };
}

}  // namespace

Exercise inverse2x2_exercise() {
  Exercise exercise;
  exercise.name = "inverse2x2";
  exercise.summary = "the closed-form 2x2 inverse, its singular test, and scaling";
  exercise.task = task_text("inverse2x2");
  exercise.stubs.python = "    raise NotImplementedError(\"not implemented: 2x2 inverse (reply inverse, or status singular)\")\n";
  exercise.stubs.cpp = "  throw std::runtime_error(\"not implemented: 2x2 inverse (reply inverse, or status singular)\");\n";
  exercise.stubs.octave = "  error('not implemented: 2x2 inverse (reply inverse, or status singular)');\n";
  exercise.battery = inverse2x2_battery;
  return exercise;
}

}  // namespace numlab::exercises
