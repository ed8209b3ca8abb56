#pragma once
// Least-squares polynomial fits y ~ b0 + b1 x + ... + bD x^D, by four methods (docs/cli.md):
//
//   normal         seed 001's curve_fit: the normal equations (V^T V) b = V^T y built from power
//                  sums, solved by the hand-written GEPP (or Gauss-Seidel);
//   normal-scaled  the same on t = (x - c) / s, with c the middle and s the half-width of the
//                  data's x range (so t fills [-1, 1]); the coefficients are then mapped back
//                  exactly to powers of the original x;
//   gsl            gsl_multifit_linear (SVD of the column-balanced Vandermonde matrix V);
//   eigen-qr       Eigen's Householder QR of V.
//
// Coefficients always come out in increasing powers of the original x.
//
// PolynomialFitter is the fit as a stepper (numlab/solver.hpp); fit_polynomial() is its solve().

#include <Eigen/Core>
#include <string>
#include <string_view>

#include "numlab/fitting/normal_equations.hpp"
#include "numlab/fitting/scaled_basis.hpp"
#include "numlab/solver.hpp"
#include "numlab/status.hpp"

namespace numlab::fitting {

enum class FitMethod { normal, normal_scaled, gsl, eigen_qr };

// The linear solver for the normal equations (normal and normal-scaled only).
enum class NormalSolver { gepp, gauss_seidel };

std::string_view to_string(FitMethod method);
std::string_view to_string(NormalSolver solver);
// Throws std::invalid_argument listing the known names.
FitMethod fit_method_from_string(std::string_view name);
NormalSolver normal_solver_from_string(std::string_view name);

struct FitOptions {
  FitMethod method = FitMethod::normal;
  int degree = 1;
  NormalSolver solver = NormalSolver::gepp;
  int max_sweeps = 100000;  // Gauss-Seidel's limit
  double sweep_tolerance = 1e-14;  // Gauss-Seidel's relative step test
};

struct PolynomialFit {
  FitMethod method = FitMethod::normal;
  int degree = 0;
  Eigen::VectorXd coefficients;  // b0 ... bD; empty when status is singular or non_finite
  Status status = Status::converged;
  int iterations = 0;                     // GEPP pivot columns or Gauss-Seidel sweeps; 1 for gsl/eigen-qr
  double residual_sd = 0.0;               // sqrt(RSS / (n - D - 1)); 0 when n = D + 1
  double r_squared = 0.0;                 // 1 - RSS / sum (y - mean y)^2; NaN when every y is equal
  // kappa of the matrix the method actually solved (see condition_of), with its columns scaled to
  // unit size first: elimination and QR give the same digits after such a scaling, so this is the
  // number that predicts the digits lost. condition_unscaled is kappa of the matrix as it stands.
  double condition_estimate = 0.0;
  double condition_unscaled = 0.0;
  std::string condition_of;               // which matrix that is, in words
  std::string condition_measure;          // how condition_estimate was measured and scaled, in words
  std::string warning;                    // empty, or why the coefficients cannot be trusted
};

// The steps of a fit, in order; gsl and eigen-qr have no system to build (their library call
// forms V itself), so they start at solve_system.
enum class FitStage {
  build_system,  // 1. the normal equations V^T V b = V^T y (on t = (x - c) / s for normal-scaled)
  solve_system,  // 2. solve them by GEPP or Gauss-Seidel (gsl, eigen-qr: the least-squares problem)
  finish_fit,    // 3. map the coefficients back to powers of x; residuals, R^2 and warnings
};

// What one step did: sent to an observer, if one is attached.
struct FitRecord {
  FitStage stage;
};

class PolynomialFitter {
 public:
  using Observer = StepObserver<PolynomialFitter, FitRecord>;

  void set_observer(Observer* observer) { observer_ = observer; }

  // Copies the data. Throws std::invalid_argument for: a negative degree, degree >= number of
  // points, x and y of different lengths, or a NaN or infinity in x or y.
  void start(const Eigen::VectorXd& x, const Eigen::VectorXd& y, const FitOptions& options);
  // Performs the next stage (FitStage). Returns false once the fit is complete.
  bool step();
  // start(), step() until done, result().
  PolynomialFit solve(const Eigen::VectorXd& x, const Eigen::VectorXd& y, const FitOptions& options);
  // The fit, complete once running() is false. A method that fails gives a status, not an exception.
  const PolynomialFit& result() const { return fit_; }

  // The contract (numlab/solver.hpp).
  bool running() const { return running_; }
  Status status() const { return status_; }
  bool stopped() const { return stopped_; }
  int iterations() const { return steps_; }  // stages done (the inner solve's count: result().iterations)
  // The coefficients so far: after stage 2 those of the solved system (in powers of t for
  // normal-scaled), after stage 3 those of the fit in powers of x (empty when the solve failed).
  const Eigen::VectorXd& x() const { return coefficients_; }

  FitStage next_stage() const { return next_; }
  const NormalEquations& normal_equations() const { return system_; }  // set by stage 1

 private:
  void build_system();
  void solve_system();
  void finish_fit();

  Observer* observer_ = nullptr;
  FitOptions options_;
  Eigen::VectorXd data_x_, data_y_;
  AffineScaling scaling_;   // t = (x - c) / s (normal-scaled only)
  NormalEquations system_;  // normal and normal-scaled only
  Eigen::VectorXd coefficients_;
  PolynomialFit fit_;
  FitStage next_ = FitStage::finish_fit;
  int steps_ = 0;
  Status status_ = Status::running;
  bool running_ = false;
  bool stopped_ = false;
};

// PolynomialFitter().solve(x, y, options): throws std::invalid_argument as its start() does.
PolynomialFit fit_polynomial(const Eigen::VectorXd& x, const Eigen::VectorXd& y, const FitOptions& options);

// p(x) by Horner's rule, coefficients in increasing powers.
double evaluate_polynomial(const Eigen::VectorXd& coefficients, double x);

}  // namespace numlab::fitting
