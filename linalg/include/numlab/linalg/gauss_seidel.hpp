#pragma once
// Gauss-Seidel iteration: seed 001's gauss_seidel, with its stop test fixed.
//
// The system it sweeps, M x = c, is chosen by Options::system:
//   normal_equations (default, as in the seed): M = A^T A, c = A^T b. M is symmetric positive
//       definite for any nonsingular A, so the sweeps always converge, but at a rate set by
//       kappa(M) = kappa(A)^2: the sweep count grows with the square of A's condition number.
//   plain (for comparison): M = A, c = b. Converges for diagonally dominant A; may diverge otherwise.
//
// One sweep (one step()):
//   for i = 1..n:  x_i <- (c_i - sum_{j != i} m_ij x_j) / m_ii     (new values used at once)
// Stop test, after each sweep:
//   ||x_k - x_{k-1}||_inf <= tolerance * max(1, ||x_k||_inf)
// (the seed compared the signed update, so any decreasing component "passed").
// Or, when Options::relative_residual_tolerance (rtol) is set, on the residual of the original system:
//   ||b - A x_k||_inf <= rtol * ||b||_inf
// Inexact Newton sets rtol per solve to its forcing term eta_k (nonlinear/forcing_term.hpp): a small
// update does not mean a small residual, and a small absolute update says nothing about a small dx.
// The residual reported is that of the ORIGINAL system, ||b - A x||_inf, never only of M x = c.
//
// The update test alone does not say x solves A x = b: on an inconsistent system (no exact
// solution) the normal equations' sweeps settle at a least-squares solution, whose residual is not
// small. So when the update test passes, x is `converged` only if its normwise backward error
//   ||b - A x||_inf / (||A||_inf ||x||_inf + ||b||_inf) <= sqrt(max(tolerance, eps))
// (x then solves a system that near A x = b; the square root leaves room for the error a slowly
// converging iteration still carries when its update passes); otherwise Status::no_progress: the
// iterates stopped moving without reaching a solution. (With rtol the stop test is the residual.)
//
// Other endings: Status::diverged when the update has grown by divergence_factor over the first
// sweep's, Status::non_finite when an infinity or NaN appears, Status::max_iterations at the limit,
// Status::singular when some m_ii = 0 (the sweep cannot divide by it).

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "numlab/linalg/input_checks.hpp"
#include "numlab/linalg/linear_result.hpp"
#include "numlab/solver.hpp"

namespace numlab::linalg {

// One row of the trace: sent to an observer after every sweep.
struct SweepRecord {
  int sweep;
  double step_norm;      // ||x_k - x_{k-1}||_inf
  double residual_norm;  // ||b - A x_k||_inf of the original system
};

struct GaussSeidelOptions {
  enum class System { normal_equations, plain };
  System system = System::normal_equations;
  double tolerance = 1e-9;         // seed 001's default
  int max_iterations = 100;        // seed 001's default
  double divergence_factor = 1e8;  // diverged when ||dx|| exceeds this times the first sweep's ||dx||
  double relative_residual_tolerance = 0.0;  // > 0: stop on ||b - A x|| <= this ||b|| instead of the update
};

template <int N = Eigen::Dynamic>
class GaussSeidel {
 public:
  using MatrixType = Matrix<N>;
  using VectorType = Vector<N>;
  // Row-major: a sweep reads M row by row.
  using WorkMatrix = Eigen::Matrix<double, N, N, (N == 1 ? Eigen::ColMajor : Eigen::RowMajor)>;
  using Observer = StepObserver<GaussSeidel<N>, SweepRecord>;

  explicit GaussSeidel(GaussSeidelOptions options = {}) : options_(options) {
    require_non_negative(options_.tolerance, "tolerance");
    require_non_negative(options_.relative_residual_tolerance, "relative residual tolerance");
    if (options_.max_iterations < 1) {
      throw std::invalid_argument("iteration limit must be at least 1, got " + std::to_string(options_.max_iterations));
    }
    if (!(options_.divergence_factor > 1.0)) {
      throw std::invalid_argument("divergence factor must exceed 1, got " + std::to_string(options_.divergence_factor));
    }
  }

  // From the next solve on, stop on ||b - A x||_inf <= rtol ||b||_inf (rtol = 0: on the update again).
  void set_relative_residual_tolerance(double rtol) {
    require_non_negative(rtol, "relative residual tolerance");
    options_.relative_residual_tolerance = rtol;
  }

  // Receives a record after every sweep; null: none.
  void set_observer(Observer* observer) { observer_ = observer; }

  void start(const MatrixType& A, const VectorType& b) { start(A, b, VectorType::Zero(A.rows())); }

  // Forms the system to sweep (A^T A and A^T b for the normal equations) and sets x = x0.
  void start(const MatrixType& A, const VectorType& b, const VectorType& x0) {
    require_valid_system(A, b);
    if (x0.size() != A.rows()) {
      throw std::invalid_argument("initial guess has " + std::to_string(x0.size()) + " entries but the matrix has " +
                                  std::to_string(A.rows()) + " rows");
    }
    require_finite(x0, "initial guess");
    n_ = static_cast<int>(A.rows());
    original_matrix_ = A;
    original_rhs_ = b;
    rhs_norm_ = b.template lpNorm<Eigen::Infinity>();
    matrix_norm_ = 0.0;
    for (Eigen::Index i = 0; i < A.rows(); ++i) matrix_norm_ = std::max(matrix_norm_, A.row(i).cwiseAbs().sum());
    if (options_.system == GaussSeidelOptions::System::normal_equations) {
      swept_matrix_.noalias() = A.transpose() * A;
      swept_rhs_.noalias() = A.transpose() * b;
    } else {
      swept_matrix_ = A;
      swept_rhs_ = b;
    }
    x_ = x0;
    residual_.resize(A.rows());  // residual_norm()'s workspace: sized here, so that step() never allocates
    sweep_ = 0;
    step_norm_ = LinearResult<N>::not_applicable;
    first_step_norm_ = 0.0;
    status_ = Status::running;
    running_ = true;
    stopped_ = false;
    if ((swept_matrix_.diagonal().array() == 0.0).any()) finish(Status::singular);
  }

  // Performs one sweep. Returns false once the iteration has ended.
  bool step() {
    if (!running_) return false;
    ++sweep_;

    // One sweep: solve equation i for x_i, using the newest values of the other unknowns.
    step_norm_ = 0.0;
    for (int i = 0; i < n_; ++i) {
      const int after = n_ - i - 1;
      const double others = swept_matrix_.row(i).head(i).dot(x_.head(i)) +
                            swept_matrix_.row(i).tail(after).dot(x_.tail(after));
      const double updated = (swept_rhs_(i) - others) / swept_matrix_(i, i);
      step_norm_ = std::max(step_norm_, std::abs(updated - x_(i)));
      x_(i) = updated;
    }
    if (sweep_ == 1) first_step_norm_ = step_norm_;

    const bool stop_asked = observer_ != nullptr &&
                            observer_->on_step(*this, {sweep_, step_norm_, residual_norm()}) == StepControl::stop;

    // Stop tests, in order of precedence.
    if (!x_.allFinite() || !std::isfinite(step_norm_)) {
      finish(Status::non_finite);
    } else if (small_enough()) {
      finish(solves_original_system() ? Status::converged : Status::no_progress);
    } else if (step_norm_ > options_.divergence_factor * std::max(first_step_norm_, options_.tolerance)) {
      finish(Status::diverged);
    } else if (sweep_ >= options_.max_iterations) {
      finish(Status::max_iterations);
    }
    if (stop_asked && running_) {  // the observer ended the run: no verdict
      running_ = false;
      stopped_ = true;
    }
    return running_;
  }

  LinearResult<N> solve(const MatrixType& A, const VectorType& b) {
    start(A, b);
    return run();
  }

  LinearResult<N> solve(const MatrixType& A, const VectorType& b, const VectorType& x0) {
    start(A, b, x0);
    return run();
  }

  LinearResult<N> result() const {
    LinearResult<N> result;
    result.x = x_;
    result.status = status_;
    result.iterations = sweep_;
    result.step_norm = step_norm_;
    result.residual_norm = residual_norm();
    return result;
  }

  // The contract (numlab/solver.hpp).
  bool running() const { return running_; }
  bool stopped() const { return stopped_; }
  Status status() const { return status_; }
  int iterations() const { return sweep_; }  // sweeps so far
  const VectorType& x() const { return x_; }

  // State between sweeps.
  double step_norm() const { return step_norm_; }
  // ||b - A x||_inf, computed as b - (A x) in a workspace kept between sweeps: with a stop on the
  // residual it is evaluated after every sweep, and a temporary would be a heap allocation each time.
  double residual_norm() const {
    residual_.noalias() = original_matrix_ * x_;
    residual_ = original_rhs_ - residual_;
    return residual_.template lpNorm<Eigen::Infinity>();
  }
  const WorkMatrix& swept_matrix() const { return swept_matrix_; }
  const VectorType& swept_rhs() const { return swept_rhs_; }

 private:
  LinearResult<N> run() {
    while (step()) {
    }
    return result();
  }

  // The stop test: the update, or (with a relative residual tolerance) the original system's residual.
  bool small_enough() const {
    if (options_.relative_residual_tolerance > 0.0) {
      return residual_norm() <= options_.relative_residual_tolerance * rhs_norm_;
    }
    return step_norm_ <= options_.tolerance * std::max(1.0, x_.template lpNorm<Eigen::Infinity>());
  }

  // Whether x, settled by the update test, solves A x = b: the backward-error test above.
  bool solves_original_system() const {
    if (options_.relative_residual_tolerance > 0.0) return true;  // the stop test was the residual
    const double allowed = std::sqrt(std::max(options_.tolerance, std::numeric_limits<double>::epsilon()));
    return residual_norm() <= allowed * (matrix_norm_ * x_.template lpNorm<Eigen::Infinity>() + rhs_norm_);
  }

  void finish(Status status) {
    status_ = status;
    running_ = false;
  }

  GaussSeidelOptions options_;
  Observer* observer_ = nullptr;
  int n_ = 0;
  MatrixType original_matrix_ = zero_or_empty<MatrixType>();
  VectorType original_rhs_ = zero_or_empty<VectorType>();
  double rhs_norm_ = 0.0;  // ||b||_inf
  double matrix_norm_ = 0.0;  // ||A||_inf
  WorkMatrix swept_matrix_ = zero_or_empty<WorkMatrix>();  // M: A^T A or A
  VectorType swept_rhs_ = zero_or_empty<VectorType>();     // c: A^T b or b
  VectorType x_ = zero_or_empty<VectorType>();
  mutable VectorType residual_ = zero_or_empty<VectorType>();  // residual_norm()'s workspace
  int sweep_ = 0;
  double step_norm_ = LinearResult<N>::not_applicable;
  double first_step_norm_ = 0.0;
  Status status_ = Status::running;
  bool running_ = false;
  bool stopped_ = false;
};

}  // namespace numlab::linalg
