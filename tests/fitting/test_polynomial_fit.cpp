// Polynomial fits on data with a known answer, the scaled basis, warnings, input checks, and the
// number parser and path splitter they rely on.

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <numbers>

#include "numlab/fitting/data_set.hpp"
#include "numlab/fitting/log_relative_error.hpp"
#include "numlab/fitting/normal_equations.hpp"
#include "numlab/fitting/path_arcs.hpp"
#include "numlab/fitting/polynomial_fit.hpp"
#include "numlab/fitting/reference_fits.hpp"
#include "numlab/fitting/scaled_basis.hpp"

using namespace numlab::fitting;

namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();

PolynomialFit fit_with(const Eigen::VectorXd& x, const Eigen::VectorXd& y, FitMethod method, int degree,
                       NormalSolver solver = NormalSolver::gepp) {
  FitOptions options;
  options.method = method;
  options.degree = degree;
  options.solver = solver;
  return fit_polynomial(x, y, options);
}

Eigen::VectorXd sample(const Eigen::VectorXd& coefficients, const Eigen::VectorXd& x) {
  Eigen::VectorXd y(x.size());
  for (Eigen::Index i = 0; i < x.size(); ++i) y(i) = evaluate_polynomial(coefficients, x(i));
  return y;
}

}  // namespace

TEST_CASE("a polynomial sampled without noise is recovered by every method", "[fitting]") {
  // 30 points on [-2, 3]; degrees 0 to 3. kappa (equilibrated) stays below 1e3 here, so every
  // method should keep 16 - 3 - 1 = 12 digits of every coefficient.
  const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(30, -2.0, 3.0);
  const Eigen::VectorXd exact_coefficients = (Eigen::VectorXd(4) << 1.5, -2.0, 0.75, 0.3).finished();
  for (int degree = 0; degree <= 3; ++degree) {
    const Eigen::VectorXd truth = exact_coefficients.head(degree + 1);
    const Eigen::VectorXd y = sample(truth, x);
    for (FitMethod method : {FitMethod::normal, FitMethod::normal_scaled, FitMethod::gsl, FitMethod::eigen_qr}) {
      for (NormalSolver solver : {NormalSolver::gepp, NormalSolver::gauss_seidel}) {
        if (solver == NormalSolver::gauss_seidel && (method == FitMethod::gsl || method == FitMethod::eigen_qr)) continue;
        INFO("degree " << degree << ", " << to_string(method) << " with " << to_string(solver));
        const PolynomialFit fit = fit_with(x, y, method, degree, solver);
        REQUIRE(fit.status == numlab::Status::converged);
        CHECK(fit.condition_estimate < 1e3);
        CHECK(fit.warning.empty());
        CHECK(min_log_relative_error(fit.coefficients, truth) >= 12.0);
        CHECK(fit.residual_sd <= 1e-12 * y.cwiseAbs().maxCoeff());
        if (degree > 0) {
          CHECK(fit.r_squared == Approx(1.0).margin(1e-12));
        } else {
          CHECK(std::isnan(fit.r_squared));  // constant y: R^2 = 1 - RSS / 0 is undefined
        }
      }
    }
  }
}

TEST_CASE("an interpolating polynomial (degree n - 1) has zero residual", "[fitting]") {
  const Eigen::VectorXd x = (Eigen::VectorXd(3) << 0.0, 1.0, 2.0).finished();
  const Eigen::VectorXd y = (Eigen::VectorXd(3) << 1.0, 3.0, 7.0).finished();  // 1 + x + x^2
  const PolynomialFit fit = fit_with(x, y, FitMethod::normal, 2);
  REQUIRE(fit.status == numlab::Status::converged);
  CHECK(fit.residual_sd == 0.0);
  CHECK(fit.coefficients.isApprox(Eigen::Vector3d(1.0, 1.0, 1.0), 1e-13));
}

TEST_CASE("the normal equations are the Hankel matrix of power sums", "[fitting]") {
  const Eigen::VectorXd x = (Eigen::VectorXd(3) << 1.0, 2.0, 3.0).finished();
  const Eigen::VectorXd y = (Eigen::VectorXd(3) << 2.0, 0.0, 1.0).finished();
  const NormalEquations system = build_normal_equations(x, y, 2);
  // Sums of x^0..x^4 are 3, 6, 14, 36, 98; of y, x y, x^2 y are 3, 5, 11.
  const Eigen::Matrix3d expected = (Eigen::Matrix3d() << 3, 6, 14, 6, 14, 36, 14, 36, 98).finished();
  CHECK(system.matrix == expected);
  CHECK(system.rhs == Eigen::Vector3d(3.0, 5.0, 11.0));
}

TEST_CASE("mapping coefficients back from t = (x - c) / s is exact algebra", "[fitting]") {
  const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(11, 1e5, 2e5);
  const AffineScaling scaling = scaling_for(x);
  CHECK(scaling.centre == 1.5e5);
  CHECK(scaling.scale == 0.5e5);
  const Eigen::VectorXd t = to_scaled(x, scaling);
  CHECK(t.minCoeff() == -1.0);
  CHECK(t.maxCoeff() == 1.0);
  // q(t) = 2 - t + 3 t^2 + 0.5 t^3, so p(x) = q((x - c) / s) must agree with q at every point.
  const Eigen::VectorXd q = (Eigen::VectorXd(4) << 2.0, -1.0, 3.0, 0.5).finished();
  const Eigen::VectorXd p = to_original_powers(q, scaling);
  for (Eigen::Index i = 0; i < x.size(); ++i) {
    // p's terms reach |q|-sized values through cancellation of terms near 3 * (x / s)^3 = 81.
    CHECK(evaluate_polynomial(p, x(i)) == Approx(evaluate_polynomial(q, t(i))).epsilon(1e3 * eps * 81));
  }
  // One exact case: q(t) = t gives p(x) = -c/s + x/s.
  const Eigen::VectorXd linear = to_original_powers(Eigen::Vector2d(0.0, 1.0), AffineScaling{4.0, 2.0});
  CHECK(linear == Eigen::Vector2d(-2.0, 0.5));
}

TEST_CASE("an ill-conditioned fit says so, a well-conditioned one does not", "[fitting][warning]") {
  // Degree 7 on 30 points of [1, 2]: the powers of x are nearly parallel there, and the plain normal
  // matrix has kappa near 1/eps even after equilibration, while GEPP still finds every pivot.
  const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(30, 1.0, 2.0);
  const Eigen::VectorXd y = (3.0 * x).array().sin();
  const Eigen::VectorXd reference = extended_precision_fit(x, y, 7);
  const PolynomialFit plain = fit_with(x, y, FitMethod::normal, 7);
  INFO("condition " << plain.condition_estimate << ", status " << to_string(plain.status));
  REQUIRE(plain.status == numlab::Status::converged);
  CHECK(plain.condition_estimate * eps >= 0.5);
  CHECK_THAT(plain.warning, Catch::Contains("condition number") && Catch::Contains("no correct digits"));
  // The warning is deserved: the coefficients are wrong in the first few digits.
  CHECK(min_log_relative_error(plain.coefficients, reference) < 4.0);
  // Scaling to [-1, 1] first: kappa 2.5e4, no warning, and the digits to show for it.
  const PolynomialFit scaled = fit_with(x, y, FitMethod::normal_scaled, 7);
  REQUIRE(scaled.status == numlab::Status::converged);
  CHECK(scaled.condition_estimate * eps < 1e-6);
  CHECK(scaled.warning.empty());
  CHECK(min_log_relative_error(scaled.coefficients, reference) >= 7.0);
}

TEST_CASE("a failed solve gives a status and no numbers passed off as a fit", "[fitting][failure]") {
  // Degree 12 on x = 0..20: GEPP meets a negligible pivot in the plain normal matrix.
  const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(21, 0.0, 20.0);
  const Eigen::VectorXd y = x.array().cos();
  const PolynomialFit singular = fit_with(x, y, FitMethod::normal, 12);
  CHECK(singular.status == numlab::Status::singular);
  CHECK(singular.coefficients.size() == 0);
  CHECK_THAT(singular.warning, Catch::Contains("negligible pivot"));
  // Gauss-Seidel that runs out of sweeps keeps its iterate, and says it is unfinished.
  FitOptions options;
  options.method = FitMethod::normal;
  options.solver = NormalSolver::gauss_seidel;
  options.degree = 3;
  options.max_sweeps = 10;
  const PolynomialFit unfinished = fit_polynomial(x, y, options);
  CHECK(unfinished.status == numlab::Status::max_iterations);
  CHECK(unfinished.iterations == 10);
  CHECK_THAT(unfinished.warning, Catch::Contains("unfinished"));
}

TEST_CASE("bad fit input is refused with a message naming it", "[fitting][input]") {
  const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(5, 0.0, 4.0);
  const Eigen::VectorXd y = x;
  CHECK_THROWS_WITH(fit_with(x, y, FitMethod::normal, -1), Catch::Contains("degree must be >= 0"));
  CHECK_THROWS_WITH(fit_with(x, y, FitMethod::normal, 5), Catch::Contains("needs at least 6 points"));
  CHECK_THROWS_WITH(fit_with(x, Eigen::VectorXd(4), FitMethod::gsl, 1), Catch::Contains("y has 4"));
  Eigen::VectorXd bad = y;
  bad(2) = std::nan("");
  CHECK_THROWS_WITH(fit_with(x, bad, FitMethod::eigen_qr, 1), Catch::Contains("non-finite"));
  CHECK_THROWS_WITH(fit_method_from_string("svd"), Catch::Contains("unknown fit method 'svd'"));
  CHECK_THROWS_WITH(normal_solver_from_string("jacobi"), Catch::Contains("unknown linear solver 'jacobi'"));
}

TEST_CASE("numbers in NIST's notation parse, anything else is refused", "[fitting][input]") {
  CHECK(parse_number("760.", "") == 760.0);
  CHECK(parse_number(".11019", "") == 0.11019);
  CHECK(parse_number("0.1E-01", "") == 0.01);
  CHECK(parse_number("-0.316081871345029E-14", "") == -0.316081871345029E-14);
  CHECK(parse_number("+3", "") == 3.0);
  for (const char* bad : {"", "abc", "1.5x", "1e", "nan", "inf", "--1", "1,5"}) {
    INFO("'" << bad << "'");
    CHECK_THROWS_AS(parse_number(bad, "here"), std::invalid_argument);
  }
  CHECK_THROWS_WITH(parse_number("abc", "f.csv line 3"), "f.csv line 3: 'abc' is not a number");
}

TEST_CASE("a closed path splits at its extreme x into an upper and a lower arc", "[fitting][arcs]") {
  // An ellipse sampled from angle 0.3 (so neither cut point is the first sample).
  constexpr int n = 40;
  Eigen::VectorXd x(n), y(n);
  for (int i = 0; i < n; ++i) {
    const double angle = 0.3 + 2.0 * std::numbers::pi * i / n;
    x(i) = 3.0 + 2.0 * std::cos(angle);
    y(i) = -1.0 + 0.5 * std::sin(angle);
  }
  const SplitPath split = split_at_extreme_x(x, y);
  CHECK(split.upper.x.size() + split.lower.x.size() == n + 2);  // the two cut points are in both
  // Between the cut points, the upper arc lies above the centre line and the lower arc below it.
  const auto interior = [](const PathArc& arc) { return arc.y.segment(1, arc.y.size() - 2).array(); };
  CHECK((interior(split.upper) > -1.0).all());
  CHECK((interior(split.lower) < -1.0).all());
  for (const PathArc* arc : {&split.upper, &split.lower}) {
    CHECK(std::is_sorted(arc->x.data(), arc->x.data() + arc->x.size()));
    CHECK(arc->x(0) == x.minCoeff());
    CHECK(arc->x(arc->x.size() - 1) == x.maxCoeff());
  }
  CHECK_THROWS_WITH(split_at_extreme_x(Eigen::VectorXd::Ones(5), Eigen::VectorXd::Zero(5)), Catch::Contains("same x"));
}

// normal-scaled on x ~ 1e200 would say converged with R^2 = -17 (degree 2). The fit in t is
// fine, but mapped back to powers of x the x^2 coefficient is ~1e-400: it underflows to 0, so the
// reported p(x) is not the fit. The least-squares check (least_squares_check.hpp) catches it.
TEST_CASE("a fit whose coefficients in powers of x are beyond the doubles is not converged", "[fitting][honesty]") {
  Eigen::VectorXd x(5), y(5);
  x << 1e200, 1.2e200, 1.5e200, 1.7e200, 2e200;
  y << 1.0, 2.0, 2.5, 2.1, 3.0;
  FitOptions options;
  options.method = FitMethod::normal_scaled;
  options.degree = 1;
  const PolynomialFit line = fit_polynomial(x, y, options);  // b1 ~ 1.6e-200: still a double
  CHECK(line.status == numlab::Status::converged);
  CHECK(line.r_squared >= 0.0);
  CHECK(line.r_squared <= 1.0);
  for (const int degree : {2, 3}) {
    options.degree = degree;
    const PolynomialFit fit = fit_polynomial(x, y, options);
    INFO("degree " << degree << ": R^2 " << fit.r_squared);
    CHECK(fit.status == numlab::Status::non_finite);
    CHECK_THAT(fit.warning, Catch::Matchers::Contains("beyond the doubles"));
  }
  // The same shape of data at x ~ 1 is fitted, and passes the check.
  options.degree = 2;
  const PolynomialFit tame = fit_polynomial(x / 1e200, y, options);
  CHECK(tame.status == numlab::Status::converged);
  CHECK(tame.r_squared >= 0.0);
  CHECK(tame.r_squared <= 1.0);
}

// y near the largest doubles: the squares in RSS and TSS overflow unless the sums are scaled, and
// R^2 = 1 - inf / inf was NaN, passed off as a statistic of a converged fit.
TEST_CASE("R^2 and the residual sd of data near 1e300 are finite and right", "[fitting][honesty]") {
  Eigen::VectorXd x(4), y(4);
  x << 0, 1, 2, 3;
  y << 1e300, -1e300, 1e300, -1e300;
  const PolynomialFit line = fit_with(x, y, FitMethod::normal_scaled, 1);
  CHECK(line.status == numlab::Status::converged);
  // The same data in units of 1e300: the statistics scale exactly (R^2 not at all).
  const PolynomialFit unit = fit_with(x, y / 1e300, FitMethod::normal_scaled, 1);
  REQUIRE(std::isfinite(line.r_squared));
  CHECK(line.r_squared == Approx(unit.r_squared).epsilon(1e-12));
  CHECK(line.residual_sd == Approx(unit.residual_sd * 1e300).epsilon(1e-12));
  // Every y equal: R^2 is undefined (NaN), and that is not a failure of the fit.
  const PolynomialFit flat = fit_with(x, Eigen::VectorXd::Constant(4, 2.0), FitMethod::normal_scaled, 1);
  CHECK(flat.status == numlab::Status::converged);
  CHECK(std::isnan(flat.r_squared));
}

// Power sums of x up to 999 to the power 2 * 60 overflow: the fit's failure, not bad input.
TEST_CASE("Normal equations that overflow give status non_finite and the entry, not an exception", "[fitting][failure]") {
  const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(1000, 0.0, 999.0);
  const PolynomialFit fit = fit_with(x, x.array().sqrt().matrix(), FitMethod::normal, 60);
  CHECK(fit.status == numlab::Status::non_finite);
  CHECK(fit.coefficients.size() == 0);
  CHECK_THAT(fit.warning, Catch::Contains("The normal equations overflow: entry ("));
  CHECK_THAT(fit.warning, Catch::Contains("is inf"));
  // Scaled to t in [-1, 1] the sums stay finite: no overflow to report.
  const PolynomialFit scaled = fit_with(x, x.array().sqrt().matrix(), FitMethod::normal_scaled, 60);
  CHECK_THAT(scaled.warning, !Catch::Contains("overflow"));
}
