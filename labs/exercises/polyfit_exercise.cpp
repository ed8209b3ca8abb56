// polyfit: the student's least-squares polynomial fit, against GSL's gsl_multifit_linear and NIST's
// certified coefficients, to the accuracy the data's conditioning allows.

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>
#include <set>

#include "exercises/detectors/polyfit_detectors.hpp"
#include "exercises/exercise_list.hpp"
#include "exercises/linkage_checks.hpp"
#include "exercises/nist_polynomial_sets.hpp"
#include "exercises/numbers.hpp"
#include "exercises/reply_fields.hpp"
#include "exercises/session.hpp"
#include "exercises/task_texts.hpp"
#include "numlab/fitting/polynomial_fit.hpp"
#include "numlab/fitting/reference_fits.hpp"

namespace numlab::exercises {

namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();

struct FitCase {
  std::string name;
  Eigen::VectorXd x, y;
  int degree;
  Eigen::VectorXd expected;   // NIST's certified values, or GSL's fit
  std::string reference;      // "NIST certified values" / "GSL gsl_multifit_linear"
};

nlohmann::json request_for(const FitCase& fit) {
  return {{"x", to_json(fit.x)}, {"y", to_json(fit.y)}, {"degree", fit.degree}};
}

// The least-squares perturbation bound (Higham, Accuracy and Stability, Thm 20.1) for a method
// that is backward stable on V with its columns scaled to unit length (QR or SVD, numpy.polyfit):
//   |S (b - b*)| / |S b*| <= c eps (kappa + kappa^2 tan(theta)),  tan(theta) = |r| / |V b*|,
// kappa = kappa_2 of the column-scaled V, S the column norms, c = 10 m (m data points).
struct Accuracy {
  double kappa, tan_theta, allowed;
  Eigen::VectorXd scale;
};

Accuracy accuracy_of(const FitCase& fit) {
  const Eigen::MatrixXd V = fitting::vandermonde(fit.x, fit.degree);
  Accuracy a;
  a.scale = V.colwise().norm().transpose();
  a.kappa = fitting::two_norm_condition(fitting::unit_columns(V));
  const Eigen::VectorXd fitted = V * fit.expected;
  a.tan_theta = (fit.y - fitted).norm() / fitted.norm();
  a.allowed = 10.0 * static_cast<double>(fit.x.size()) * eps * (a.kappa + a.kappa * a.kappa * a.tan_theta);
  return a;
}

double scaled_error(const Eigen::VectorXd& got, const FitCase& fit, const Accuracy& a, int& worst) {
  const Eigen::VectorXd weighted = (a.scale.array() * (got - fit.expected).array()).abs().matrix();
  weighted.maxCoeff(&worst);
  return weighted.maxCoeff() / (a.scale.array() * fit.expected.array()).abs().maxCoeff();
}

std::vector<ReferenceTime> fit_times(const FitCase& fit) {
  fitting::FitOptions options;
  options.degree = fit.degree;
  options.method = fitting::FitMethod::normal_scaled;
  return {{"numlab fit (normal-scaled, GEPP)", median_seconds([&] { fitting::fit_polynomial(fit.x, fit.y, options); })},
          {"GSL gsl_multifit_linear", median_seconds([&] { fitting::gsl_multifit_fit(fit.x, fit.y, fit.degree); })}};
}

// True when `got` in reverse order matches, and reversal changes the answer (on Wampler1, whose
// certified coefficients are all 1, it changes nothing: no evidence for reversed powers there).
bool reversal_matches(const Eigen::VectorXd& got, const FitCase& fit, const Accuracy& a, double tolerance) {
  int unused = 0;
  return scaled_error(got.reverse(), fit, a, unused) <= tolerance &&
         scaled_error(fit.expected.reverse(), fit, a, unused) > a.allowed;
}

std::optional<Diagnosis> diagnosis_for(const FitCase& fit, const Accuracy& a, const Eigen::VectorXd& got) {
  return detectors::diagnose_polyfit({fit.x, fit.y, fit.degree, fit.expected, a.allowed}, got);
}

std::string fit_hint(const Eigen::VectorXd& got, const FitCase& fit, const Accuracy& a) {
  if (reversal_matches(got, fit, a, 1e-6)) {
    return "the powers are reversed: reply lowest power first (numpy.polyfit returns the highest first)";
  }
  return "solve the least-squares problem min |V b - y| stably (QR or SVD of V, columns scaled to unit length); the "
         "normal equations square kappa";
}

// The words a polyfit reply's status may be: "converged" (with coefficients; the same as no status)
// and "singular" (the fit is not determined). Any other word is a failure, never a pass.
const std::vector<std::string> status_words = {"converged", "singular"};

std::string listed_status_words() {
  std::string listed;
  for (const std::string& word : status_words) listed += (listed.empty() ? "\"" : ", \"") + word + "\"";
  return listed;
}

bool known_status_word(const std::string& word) {
  return std::find(status_words.begin(), status_words.end(), word) != status_words.end();
}

// "" or the sentence saying that `status` is not one of polyfit's status words.
std::string unknown_status_note(const std::optional<std::string>& status) {
  if (!status || known_status_word(*status)) return "";
  return fmt::format("; \"{}\" is not a status word of polyfit (the words: {})", *status, listed_status_words());
}

// A determined fit's reply gives coefficients, with no status or "converged"; else a failed Verdict.
std::optional<Verdict> wrong_status(const nlohmann::json& reply, const FitCase& fit) {
  const auto status = optional_status(reply);
  if (!status || *status == "converged") return std::nullopt;
  return Verdict::fail(fmt::format("{} (degree {}, {} points): the reply gives status \"{}\"{}; this fit is "
                                   "determined, so expected coefficients with status \"converged\" (or no status)",
                                   fit.name, fit.degree, fit.x.size(), *status, unknown_status_note(status)),
                       "reply \"singular\" only when fewer distinct x than degree + 1 leave the fit undetermined");
}

// The coefficients of a reply, or a failed Verdict for a wrong count (a wrong degree is the
// student's mistake, not a broken reply).
std::optional<Verdict> wrong_count(const nlohmann::json& reply, const FitCase& fit) {
  const auto found = reply.find("coefficients");
  if (found == reply.end() || !found->is_array() || found->size() == static_cast<std::size_t>(fit.degree + 1)) {
    return std::nullopt;  // vector_field reports a missing or malformed field
  }
  std::optional<Diagnosis> diagnosis;
  try {
    const Eigen::VectorXd got = vector_field(reply, "coefficients", static_cast<Eigen::Index>(found->size()));
    diagnosis = detectors::diagnose_polyfit({fit.x, fit.y, fit.degree, fit.expected, accuracy_of(fit).allowed}, got);
  } catch (const ReplyError&) {
  }
  return Verdict::fail(fmt::format("{}: coefficients has {} entries, expected degree + 1 = {} (b0 ... b{})", fit.name,
                                   found->size(), fit.degree + 1, fit.degree),
                       std::move(diagnosis), "a loop over the powers that stops one short, or starts at 1: the constant term b0 comes first");
}

Verdict check_fits(Session& session, const std::vector<FitCase>& cases) {
  for (const FitCase& fit : cases) {
    const nlohmann::json reply = session.ask(request_for(fit));
    session.expect({fmt::format("{}, degree {}, {} points", fit.name, fit.degree, fit.x.size()),
                    {{"coefficients", to_json(fit.expected)}},
                    fmt::format("the coefficients within {} of {} above (relative, each weighted by its column's norm)",
                                sci(accuracy_of(fit).allowed), fit.reference)});
    if (auto verdict = wrong_status(reply, fit)) return *verdict;
    if (auto verdict = wrong_count(reply, fit)) return *verdict;
    const Eigen::VectorXd got = vector_field(reply, "coefficients", fit.degree + 1);
    const Accuracy a = accuracy_of(fit);
    int worst = 0;
    const double error = scaled_error(got, fit, a, worst);
    if (error <= a.allowed) continue;
    return Verdict::fail(
        fmt::format("{} (degree {}, {} points): coefficients[{}] = {}, expected {} ({}, {}); the coefficients "
                    "differ by {} (relative, each weighted by its column's norm), allowed {} (10 m eps (kappa + "
                    "kappa^2 tan theta), kappa = {}, tan theta = {})",
                    fit.name, fit.degree, fit.x.size(), worst, digits17(got(worst)), digits17(fit.expected(worst)),
                    fit.reference, difference(got(worst), fit.expected(worst)), sci(error),
                    sci(a.allowed), sci(a.kappa), sci(a.tan_theta)) +
            (reversal_matches(got, fit, a, a.allowed) ? "; in reverse order your coefficients match: powers reversed"
                                                      : ""),
        diagnosis_for(fit, a, got), fit_hint(got, fit, a));
  }
  return Verdict::pass(fit_times(cases.back()));
}

FitCase gsl_case(std::string name, Eigen::VectorXd x, Eigen::VectorXd y, int degree) {
  Eigen::VectorXd expected = fitting::gsl_multifit_fit(x, y, degree).coefficients;
  return {std::move(name), std::move(x), std::move(y), degree, std::move(expected), "GSL gsl_multifit_linear"};
}

// A number with one decimal drawn from a variant's stream.
double tenths(Variant::Stream& stream, double low, double high) { return std::round(stream.uniform(low, high) * 10.0) / 10.0; }

// The line, the interpolating parabola and the noisy cubic; with a variant, their data drawn from it
// (the same shapes: 5 points on a noisy line, 3 distinct x at least 0.5 apart, 12 points of a cubic
// plus 0.1 sin(w x)).
std::vector<FitCase> small_cases(const Variant& variant) {
  std::vector<FitCase> cases;
  Variant::Stream stream = variant.stream(1);
  Eigen::VectorXd x(5), y(5);
  x << 0, 1, 2, 3, 4;
  y << 2.1, 4.9, 8.2, 10.8, 14.1;
  if (variant.active()) {
    const double c0 = tenths(stream, -5, 5), c1 = tenths(stream, -3, 3);
    for (Eigen::Index i = 0; i < 5; ++i) y(i) = std::round((c0 + c1 * x(i) + stream.uniform(-0.3, 0.3)) * 10.0) / 10.0;
  }
  cases.push_back(gsl_case("a line through 5 points", x, y, 1));
  Eigen::VectorXd x3(3), y3(3);
  x3 << -1, 0.5, 2;
  y3 << 4, 1, 7;
  if (variant.active()) {
    x3 << tenths(stream, -2, -1), tenths(stream, -0.5, 0.5), tenths(stream, 1, 3);
    y3 << tenths(stream, -5, 8), tenths(stream, -5, 8), tenths(stream, -5, 8);
  }
  cases.push_back(gsl_case("a parabola through 3 points (interpolation)", x3, y3, 2));
  Eigen::VectorXd x12 = Eigen::VectorXd::LinSpaced(12, -1.0, 2.0), y12(12);
  double p[4] = {1.5, -2.0, 0.0, 0.5}, w = 7.0;
  if (variant.active()) {
    for (double& coefficient : p) coefficient = tenths(stream, -3, 3);
    if (p[3] == 0.0) p[3] = 0.5;  // a cubic
    w = tenths(stream, 5, 9);
  }
  for (Eigen::Index i = 0; i < 12; ++i) {
    y12(i) = p[0] + p[1] * x12(i) + p[2] * x12(i) * x12(i) + p[3] * std::pow(x12(i), 3) + 0.1 * std::sin(w * x12(i));
  }
  cases.push_back(gsl_case("a cubic through 12 noisy points", x12, y12, 3));
  return cases;
}

Verdict nist_fits(Session& session) {
  std::vector<FitCase> cases;
  for (fitting::DataSet& set : nist_polynomial_sets()) {
    const auto& certified = set.certified->parameters;
    Eigen::VectorXd expected = Eigen::Map<const Eigen::VectorXd>(certified.data(), static_cast<Eigen::Index>(certified.size()));
    const int degree = static_cast<int>(certified.size()) - 1;
    cases.push_back({set.name, set.x, set.y, degree, expected, "NIST certified values"});
  }
  return check_fits(session, cases);
}

// An exact degree-9 polynomial at 30 points of [0, 1]: V with unit columns has kappa ~ 2.3e6, so a
// backward-stable solve (QR or SVD) keeps about 1e-11 where 10 m eps kappa allows 1.5e-7, and the
// normal equations, scaled or not, square kappa and lose about 1e-4.
Verdict ill_conditioned_fit(Session& session) {
  const int degree = 9;
  const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(30, 0.0, 1.0);
  Eigen::VectorXd coefficients(degree + 1);
  for (int k = 0; k <= degree; ++k) coefficients(k) = (k % 2 == 0 ? 1.0 : -1.0) * (1.0 + 0.5 * k);
  const Eigen::VectorXd y = fitting::vandermonde(x, degree) * coefficients;
  return check_fits(session, {{"an exact degree-9 polynomial at 30 points of [0, 1] (kappa ~ 2.3e6)", x, y, degree,
                               coefficients, "the generating polynomial"}});
}

// Fewer distinct x than coefficients: the fit is not determined, and must say so.
Verdict undetermined(Session& session) {
  const std::vector<std::pair<std::vector<double>, int>> cases = {{{1, 1, 1, 1, 2, 2, 2, 2}, 2}, {{0.5, 1.5, 2.5}, 3}};
  for (const auto& [xs, degree] : cases) {
    Eigen::VectorXd x = Eigen::Map<const Eigen::VectorXd>(xs.data(), static_cast<Eigen::Index>(xs.size()));
    Eigen::VectorXd y = x.array() * 2.0 + 1.0;
    const std::size_t distinct = std::set<double>(xs.begin(), xs.end()).size();
    const nlohmann::json reply = session.ask({{"x", to_json(x)}, {"y", to_json(y)}, {"degree", degree}});
    const auto status = optional_status(reply);
    if (status != "singular") {
      return Verdict::fail(fmt::format("{} points with {} distinct x, degree {}: the reply gives status \"{}\"{}; {} "
                                       "coefficients are not determined by {} distinct x (V has rank {}); expected a "
                                       "status saying so: \"singular\"",
                                       xs.size(), distinct, degree, status.value_or("(none)"),
                                       unknown_status_note(status), degree + 1, distinct, distinct),
                           status.value_or("converged") != "converged"
                               ? std::nullopt
                               : std::optional<Diagnosis>(detectors::undetermined_fit(xs.size(), distinct, degree)),
                           "check the rank of V (or the count of distinct x) before solving; a least-squares solver "
                           "returns some answer even when infinitely many fit equally well");
    }
  }
  return Verdict::pass();
}

}  // namespace

Exercise polyfit_exercise() {
  Exercise exercise;
  exercise.name = "polyfit";
  exercise.summary = "least-squares polynomial fit, against GSL and NIST's certified values";
  exercise.task = task_text("polyfit");
  exercise.stubs.python = "    raise NotImplementedError(\"not implemented: the least-squares polynomial fit\")\n";
  exercise.stubs.cpp = "  throw std::runtime_error(\"not implemented: the least-squares polynomial fit\");\n";
  exercise.stubs.octave = "  error('not implemented: the least-squares polynomial fit');\n";
  exercise.battery = [](const Variant& variant) {
    return std::vector<Check>{
        {"Small fits (a line, an interpolating parabola, a noisy cubic) match GSL's gsl_multifit_linear, lowest power "
         "first",
         1, [cases = small_cases(variant)](Session& session) { return check_fits(session, cases); }},
        {"NIST StRD polynomial sets match the certified coefficients to the accuracy kappa allows", 2, nist_fits},
        {"An ill-conditioned exact fit (degree 9, 30 points in [0, 1]) is as accurate as kappa allows, not kappa^2", 2,
         ill_conditioned_fit},
        {"A fit with fewer distinct x than coefficients reports status \"singular\"", 3, undetermined},
    };
  };
  return exercise;
}

}  // namespace numlab::exercises
