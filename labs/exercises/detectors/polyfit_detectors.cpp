#include "exercises/detectors/polyfit_detectors.hpp"

#include <Eigen/LU>
#include <cmath>
#include <fmt/format.h>
#include <limits>
#include <vector>

#include "exercises/detectors/explains.hpp"
#include "exercises/detectors/unstable_fits.hpp"
#include "numlab/fitting/reference_fits.hpp"

namespace numlab::exercises::detectors {

namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();

// max_k |S_k (got_k - h_k)| / max_k |S_k h_k|: the check's measure, S the column norms of V.
double weighted(const Eigen::VectorXd& got, const Eigen::VectorXd& h, const Eigen::VectorXd& S) {
  if (got.size() != h.size() || h.size() != S.size() || !got.allFinite() || !h.allFinite()) {
    return std::numeric_limits<double>::infinity();
  }
  const double scale = (S.array() * h.array()).abs().maxCoeff();
  const double difference = (S.array() * (got - h).array()).abs().maxCoeff();
  return scale > 0.0 ? difference / scale : difference;
}

Eigen::VectorXd column_norms(const Eigen::VectorXd& x, int degree) {
  return fitting::vandermonde(x, degree).colwise().norm().transpose();
}

// 10 m eps (kappa + kappa^2 tan theta) for V(x) with unit columns and the fit h.
double accuracy(const Eigen::VectorXd& x, const Eigen::VectorXd& y, const Eigen::VectorXd& h) {
  const Eigen::MatrixXd V = fitting::vandermonde(x, static_cast<int>(h.size()) - 1);
  const double kappa = fitting::two_norm_condition(fitting::unit_columns(V));
  const Eigen::VectorXd fitted = V * h;
  const double tan_theta = (y - fitted).norm() / fitted.norm();
  return 10.0 * static_cast<double>(x.size()) * eps * (kappa + kappa * kappa * tan_theta);
}

struct Change {
  const char* name;  // "t = (x - mean) / std"
  double centre, scale;
};

std::vector<Change> changes_of_variable(const Eigen::VectorXd& x) {
  const double m = static_cast<double>(x.size());
  const double mean = x.mean();
  const double spread = std::sqrt((x.array() - mean).square().sum() / m);
  const double sample = m > 1 ? std::sqrt((x.array() - mean).square().sum() / (m - 1)) : spread;
  const double low = x.minCoeff(), high = x.maxCoeff();
  std::vector<Change> changes = {
      {"t = x - mean(x)", mean, 1.0},
      {"t = (x - mean(x)) / std(x)", mean, spread},
      {"t = (x - mean(x)) / std(x) (sample std)", mean, sample},
      {"t = (x - mid) / half-width (t in [-1, 1])", (low + high) / 2.0, (high - low) / 2.0},
      {"t = (x - min) / (max - min) (t in [0, 1])", low, high - low},
      {"t = x / max|x|", 0.0, x.cwiseAbs().maxCoeff()},
      {"t = (x - mean(x)) / max|x - mean(x)|", mean, (x.array() - mean).abs().maxCoeff()},
  };
  std::vector<Change> usable;
  for (const Change& change : changes) {
    if (change.scale > 0.0 && std::isfinite(change.scale)) usable.push_back(change);
  }
  return usable;
}

// Normal equations N b = r with one known wrong power sum, solved in long double.
Eigen::VectorXd wrong_normal_equations(const Eigen::VectorXd& x, const Eigen::VectorXd& y, int degree, int variant) {
  using Matrix = Eigen::Matrix<long double, Eigen::Dynamic, Eigen::Dynamic>;
  using Vector = Eigen::Matrix<long double, Eigen::Dynamic, 1>;
  const int size = degree + 1;
  const auto power_sum = [&](int power, bool with_y) {
    long double sum = 0.0L;
    for (Eigen::Index i = 0; i < x.size(); ++i) {
      sum += std::pow(static_cast<long double>(x(i)), power) * (with_y ? static_cast<long double>(y(i)) : 1.0L);
    }
    return sum;
  };
  Matrix N(size, size);
  Vector r(size);
  for (int j = 0; j < size; ++j) {
    for (int k = 0; k < size; ++k) N(j, k) = power_sum(j + k + (variant == 0 ? 1 : 0), false);
    r(j) = power_sum(j + (variant == 1 ? 1 : 0), true);
  }
  if (variant == 2) N(0, 0) = 1.0L;  // S_0 = m written as 1
  return N.fullPivLu().solve(r).cast<double>();
}

const char* const wrong_sums[] = {"the power sums S_(j+k+1) in place of S_(j+k)",
                                  "the moments sum x^(j+1) y in place of sum x^j y",
                                  "S_0 = 1 in place of the number of points m"};

// The scales a student divides V's columns by: each scaled fit's coefficients are the fit's times
// the scales, and must be divided by them afterwards.
struct ColumnScales {
  const char* name;
  Eigen::VectorXd d;
};

std::vector<ColumnScales> column_scales(const Eigen::VectorXd& x, int degree) {
  const Eigen::MatrixXd V = fitting::vandermonde(x, degree);
  std::vector<ColumnScales> scales = {{"its 2-norm", V.colwise().norm().transpose()},
                                      {"its largest |entry|", V.cwiseAbs().colwise().maxCoeff().transpose()},
                                      {"its 1-norm", V.cwiseAbs().colwise().sum().transpose()}};
  std::vector<ColumnScales> usable;
  for (ColumnScales& scale : scales) {
    if ((scale.d.array() > 0.0).all() && scale.d.allFinite()) usable.push_back(std::move(scale));
  }
  return usable;
}

// The centre c and scale s of the variable t = (x - c) / s in which `got` would be the fit: q(t) =
// p(c + s t) gives q_D = p_D s^D and q_(D-1) = s^(D-1) (p_(D-1) + D p_D c) (p the reference).
// Nothing when they do not solve (degree < 2 leaves nothing to check them by: two numbers, two
// unknowns).
std::optional<Change> solved_change(const Eigen::VectorXd& got, const Eigen::VectorXd& p, int D) {
  if (D < 2 || got.size() != D + 1 || p.size() != D + 1 || p(D) == 0.0) return std::nullopt;
  const double ratio = got(D) / p(D);
  if (!(D % 2 == 1 || ratio > 0.0) || ratio == 0.0) return std::nullopt;
  const double s = std::copysign(std::pow(std::abs(ratio), 1.0 / D), ratio);
  const double c = (got(D - 1) / std::pow(s, D - 1) - p(D - 1)) / (D * p(D));
  if (!std::isfinite(s) || !std::isfinite(c) || !(s > 0.0)) return std::nullopt;
  return Change{"t = (x - c) / s, c and s solved from your two highest coefficients", c, s};
}

}  // namespace

std::optional<Diagnosis> diagnose_polyfit(const PolyfitProblem& p, const Eigen::VectorXd& got) {
  const int D = p.degree;
  const Eigen::VectorXd S = column_norms(p.x, D);
  std::vector<Detector> detectors;
  // Another count: the fit of that degree.
  if (got.size() != D + 1 && got.size() >= 1) {
    detectors.push_back({"degree_off_by_one", Specificity::exact, [&]() -> std::optional<std::string> {
                           const int other = static_cast<int>(got.size()) - 1;
                           if (std::abs(other - D) != 1) return std::nullopt;
                           const Eigen::VectorXd h = fitting::gsl_multifit_fit(p.x, p.y, other).coefficients;
                           const double distance = weighted(got, h, column_norms(p.x, other));
                           if (!(distance <= std::max(1e-6, accuracy(p.x, p.y, h)))) return std::nullopt;
                           return fmt::format("your {} coefficients are the least-squares fit of degree {} to {}: the "
                                              "fit of degree {} has {} coefficients, b0 ... b{} (V has columns x^0 ... "
                                              "x^{})",
                                              got.size(), other, measured(distance), D, D + 1, D, D);
                         }});
    detectors.push_back({"degree_off_by_one", Specificity::family, [&]() -> std::optional<std::string> {
                           if (std::abs(static_cast<int>(got.size()) - 1 - D) != 1) return std::nullopt;
                           return fmt::format("you sent {} coefficients for degree {}: a loop over the powers one short "
                                              "or one long; degree {} has {} coefficients, b0 ... b{}",
                                              got.size(), D, D, D + 1, D);
                         }});
    return diagnose(detectors);
  }
  const double reference_distance = weighted(got, p.expected, S);
  detectors.push_back({"powers_reversed", Specificity::exact, [&]() -> std::optional<std::string> {
                         const double distance = weighted(got.reverse(), p.expected, S);
                         const double separation = weighted(p.expected.reverse(), p.expected, S);
                         if (!explains(distance, separation, p.allowed, p.allowed)) return std::nullopt;
                         return fmt::format("reversed, your coefficients match the reference to {} (reversal changes "
                                            "the reference by {}): reply lowest power first, b0 ... b{} (numpy.polyfit "
                                            "returns the highest first)",
                                            measured(distance), measured(separation), D);
                       }});
  detectors.push_back({"degree_off_by_one", Specificity::exact, [&]() -> std::optional<std::string> {
                         if (D < 1 || got(D) != 0.0) return std::nullopt;
                         const Eigen::VectorXd h = fitting::gsl_multifit_fit(p.x, p.y, D - 1).coefficients;
                         const double distance = weighted(got.head(D), h, column_norms(p.x, D - 1));
                         if (!(distance <= std::max(1e-6, accuracy(p.x, p.y, h)))) return std::nullopt;
                         return fmt::format("your b{} is 0 and b0 ... b{} are the fit of degree {} to {}: V needs the "
                                            "columns x^0 ... x^{}",
                                            D, D - 1, D - 1, measured(distance), D);
                       }});
  for (const Change& change : changes_of_variable(p.x)) {
    detectors.push_back({"missing_unscale", Specificity::exact, [&, change]() -> std::optional<std::string> {
                           const Eigen::VectorXd t = (p.x.array() - change.centre) / change.scale;
                           const Eigen::VectorXd h = fitting::gsl_multifit_fit(t, p.y, D).coefficients;
                           const double distance = weighted(got, h, column_norms(t, D));
                           const double separation = weighted(h, p.expected, S);
                           if (!explains(distance, separation, accuracy(t, p.y, h), p.allowed)) return std::nullopt;
                           return fmt::format("your coefficients are those of the fit in {} (centre {}, scale {}) to {}, "
                                              "read as powers of x they are off by {}: map them back to powers of x, "
                                              "p(x) = q((x - c) / s)",
                                              change.name, measured(change.centre), measured(change.scale),
                                              measured(distance), measured(separation));
                         }});
  }
  if (const std::optional<Change> change = solved_change(got, p.expected, D)) {
    detectors.push_back({"missing_unscale", Specificity::exact, [&, change = *change]() -> std::optional<std::string> {
                           const Eigen::VectorXd t = (p.x.array() - change.centre) / change.scale;
                           const Eigen::VectorXd h = fitting::gsl_multifit_fit(t, p.y, D).coefficients;
                           const double distance = weighted(got, h, column_norms(t, D));
                           const double separation = weighted(h, p.expected, S);
                           if (!explains(distance, separation, std::max(p.allowed, accuracy(t, p.y, h)), p.allowed)) {
                             return std::nullopt;
                           }
                           return fmt::format("your {} coefficients are those of the fit in t = (x - c) / s with c = {} "
                                              "and s = {} (solved from your two highest) to {}; read as powers of x "
                                              "they are off by {}: map them back to powers of x, p(x) = q((x - c) / s)",
                                              D + 1, measured(change.centre), measured(change.scale),
                                              measured(distance), measured(separation));
                         }});
  }
  for (const ColumnScales& scale : column_scales(p.x, D)) {
    for (const int power : {1, 2}) {
      detectors.push_back({"missing_unscale", Specificity::exact, [&, scale, power]() -> std::optional<std::string> {
                             const Eigen::VectorXd factor = scale.d.array().pow(power);
                             const double distance = weighted(got.cwiseQuotient(factor), p.expected, S);
                             const double separation = weighted(p.expected.cwiseProduct(factor), p.expected, S);
                             if (!explains(distance, separation, p.allowed, p.allowed)) return std::nullopt;
                             return fmt::format("your coefficients are the fit's times {} of V's columns ({}): divided "
                                                "by {}, they match the reference to {} (as they stand they are off by "
                                                "{}): after solving with column k divided by d_k, b_k = (your "
                                                "solution)_k / d_k",
                                                power == 1 ? "the scales" : "the squares of the scales",
                                                fmt::format("d_k = {}", scale.name),
                                                power == 1 ? "d_k" : "d_k^2", measured(distance), measured(separation));
                           }});
    }
  }
  for (const bool first : {true, false}) {
    detectors.push_back({"interpolation", Specificity::exact, [&, first]() -> std::optional<std::string> {
                           if (p.x.size() <= D + 1) return std::nullopt;
                           const Eigen::Index start = first ? 0 : p.x.size() - (D + 1);
                           const Eigen::VectorXd xs = p.x.segment(start, D + 1), ys = p.y.segment(start, D + 1);
                           const Eigen::MatrixXd V = fitting::vandermonde(xs, D);
                           const Eigen::VectorXd h = V.fullPivLu().solve(ys);
                           const double kappa = fitting::two_norm_condition(fitting::unit_columns(V));
                           const double distance = weighted(got, h, S);
                           const double separation = weighted(h, p.expected, S);
                           if (!explains(distance, separation, 100.0 * (D + 1) * eps * kappa, p.allowed)) {
                             return std::nullopt;
                           }
                           return fmt::format("your coefficients are the polynomial through the {} {} points to {} "
                                              "(it differs from the least-squares fit of all {} by {}): fit all the "
                                              "points in least squares, min |V b - y|",
                                              first ? "first" : "last", D + 1, measured(distance), p.x.size(),
                                              measured(separation));
                         }});
  }
  for (int variant = 0; variant < 3; ++variant) {
    detectors.push_back({"normal_equations_wrong", Specificity::exact, [&, variant]() -> std::optional<std::string> {
                           const Eigen::VectorXd h = wrong_normal_equations(p.x, p.y, D, variant);
                           const double distance = weighted(got, h, S);
                           const double separation = weighted(h, p.expected, S);
                           if (!explains(distance, separation, p.allowed, p.allowed)) return std::nullopt;
                           return fmt::format("your coefficients solve normal equations built with {} to {} (they are "
                                              "off by {}): V^T V has entries sum x^(j+k), V^T y has sum x^j y; better, "
                                              "solve min |V b - y| by QR or SVD of V with unit columns",
                                              wrong_sums[variant], measured(distance), measured(separation));
                         }});
  }
  // No replay explains the numbers exactly: how far they are, against what each unstable method
  // the task rules out loses on these data (replayed and measured here). The method whose loss is
  // nearest the student's (within a factor of 1000) is named: a family, since other codes of the
  // same method lose other digits.
  const Eigen::MatrixXd V = fitting::vandermonde(p.x, D);
  const double kappa_unscaled = fitting::two_norm_condition(V);
  const double kappa = fitting::two_norm_condition(fitting::unit_columns(V));
  const double svd_loss = weighted(unscaled_svd_fit(p.x, p.y, D), p.expected, S);
  const double normal_loss = weighted(power_sum_normal_fit(p.x, p.y, D), p.expected, S);
  const auto gap = [reference_distance](double loss) {  // decades between the student's loss and `loss`
    return std::isfinite(loss) && loss > 0.0 ? std::abs(std::log10(reference_distance / loss)) : 1e300;
  };
  const auto nearest = [&](double loss, double other) {
    return reference_distance > p.allowed && std::isfinite(reference_distance) && gap(loss) <= 3.0 &&
           gap(loss) < gap(other);
  };
  const std::string measured_losses =
      fmt::format("your coefficients are off by {}, allowed {} (a stable solve of V with unit columns, kappa = {}); "
                  "replayed on these data, an SVD of V with its columns as they are (Golub-Reinsch) is off by {}, the "
                  "normal equations from power sums of x by {}",
                  measured(reference_distance), measured(p.allowed), measured(kappa), measured(svd_loss),
                  measured(normal_loss));
  struct Unstable {
    const char* cause;
    double loss, other;
    std::string verdict;
  };
  const std::vector<Unstable> unstable = {
      {"unscaled_vandermonde", svd_loss, normal_loss,
       fmt::format("yours is an unscaled V's loss (kappa = {} with its columns as they are): scale each column of V to "
                   "unit length, solve by QR or SVD, divide b_k by column k's norm",
                   measured(kappa_unscaled))},
      {"normal_equations_wrong", normal_loss, svd_loss,
       fmt::format("yours is the normal equations' loss, formed from unscaled columns they square kappa(V) = {}: solve "
                   "min |V b - y| by QR or SVD of V with unit columns",
                   measured(kappa_unscaled))},
  };
  for (const Unstable& method : unstable) {
    detectors.push_back({method.cause, Specificity::family, [=]() -> std::optional<std::string> {
                           if (!nearest(method.loss, method.other)) return std::nullopt;
                           return measured_losses + ": " + method.verdict;
                         }});
  }
  return diagnose(detectors);
}

Diagnosis undetermined_fit(std::size_t points, std::size_t distinct, int degree) {
  return {"no_rank_check", Specificity::family,
          fmt::format("you sent coefficients for {} points with {} distinct x and degree {}: V has rank {} < {}, so "
                      "infinitely many fits are equally good; count the distinct x (or test V's rank) before "
                      "solving and reply \"singular\"",
                      points, distinct, degree, distinct, degree + 1)};
}

}  // namespace numlab::exercises::detectors
