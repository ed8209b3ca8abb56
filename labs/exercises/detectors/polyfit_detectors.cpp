#include "exercises/detectors/polyfit_detectors.hpp"

#include <Eigen/LU>
#include <cmath>
#include <fmt/format.h>
#include <limits>
#include <vector>

#include "exercises/detectors/explains.hpp"
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

}  // namespace

std::optional<Diagnosis> diagnose_polyfit(const PolyfitProblem& p, const Eigen::VectorXd& got) {
  const int D = p.degree;
  const Eigen::VectorXd S = column_norms(p.x, D);
  const double m = static_cast<double>(p.x.size());
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
  // No replay explains the numbers: how far they are, against what each unstable method loses.
  const Eigen::MatrixXd V = fitting::vandermonde(p.x, D);
  const double kappa_unscaled = fitting::two_norm_condition(V);
  const double kappa = fitting::two_norm_condition(fitting::unit_columns(V));
  const Eigen::VectorXd fitted = V * p.expected;
  const double tan_theta = (p.y - fitted).norm() / fitted.norm();
  const double unscaled = 10.0 * m * eps * (kappa_unscaled + kappa_unscaled * kappa_unscaled * tan_theta);
  const double normal = 10.0 * m * eps * kappa_unscaled * kappa_unscaled;
  detectors.push_back({"unscaled_vandermonde", Specificity::family, [=]() -> std::optional<std::string> {
                         if (!(reference_distance > p.allowed && reference_distance <= unscaled && unscaled < 1.0)) {
                           return std::nullopt;
                         }
                         return fmt::format("your coefficients are off by {}: more than the {} a stable solve of V with "
                                            "unit columns allows (kappa = {}), within the {} an unscaled V loses (kappa "
                                            "= {}): scale each column of V to unit length, solve by QR or SVD, divide "
                                            "b_k by column k's norm",
                                            measured(reference_distance), measured(p.allowed), measured(kappa),
                                            measured(unscaled), measured(kappa_unscaled));
                       }});
  detectors.push_back({"normal_equations_wrong", Specificity::family, [=]() -> std::optional<std::string> {
                         if (!(reference_distance > std::max(p.allowed, unscaled) && reference_distance <= normal &&
                               normal < 1.0)) {
                           return std::nullopt;
                         }
                         return fmt::format("your coefficients are off by {}: more than an unscaled V loses ({}), "
                                            "within what the normal equations V^T V b = V^T y lose ({}: they square "
                                            "kappa(V) = {}): solve min |V b - y| by QR or SVD of V with unit columns",
                                            measured(reference_distance), measured(unscaled), measured(normal),
                                            measured(kappa_unscaled));
                       }});
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
