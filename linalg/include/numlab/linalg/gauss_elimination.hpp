#pragma once
// Gaussian elimination with partial pivoting (GEPP): seed 001's gauss_elim, done properly.
//
// For each column k:
//   1. find the pivot   - the row p >= k with the largest |a_pk|;
//   2. swap             - if p != k, exchange rows k and p (of A and b, and of the multipliers
//                         l_ij, j < k, kept so far); P records the swap;
//   3. eliminate        - for every row i below k: l_ik = a_ik / a_kk, row_i -= l_ik * row_k;
//                         l_ik is kept, as column k of L.
// Then:
//   4. back-substitute  - x_i = (c_i - sum_{j>i} u_ij x_j) / u_ii, from the last unknown up,
//                         column by column (each x_i is subtracted from the c_j above it at once),
//                         multiplying by the 1/u_ii kept from step 3.
//
// A pivot that is zero relative to the matrix's scale (|a_kk| <= tol * max|a_ij|, tol = n*eps by
// default) ends the solve with Status::singular: there is never a division by a negligible pivot.
// The growth factor max|u_ij| / max|a_ij| is reported; it bounds how much rounding error the
// elimination can amplify (2^(n-1) at worst, reached by Wilkinson's matrix).
//
// Steps 1-3 factor A: PA = LU, L unit lower triangular (the multipliers), U upper triangular, P the
// row swaps; they hold as P A = L R after every column, R the reduced matrix. lower(), upper() and
// permutation() give them; solve_with_factors(b) solves A x = b for another b with them (factor
// once, solve many): P b, then step 3's updates of b with the kept l_ik, then step 4, the same
// operations in the same order as a fresh solve, so the same x bit for bit.
//
// The stepper below is the textbook: one step() is one pivot column (steps 1-3) or one
// back-substituted unknown, and an observer sees each. solve() and solve_prechecked() without an
// observer run the same arithmetic as one loop (gauss_elimination_kernel.hpp), bit for bit the
// same x. Fixed sizes (N = 2, 8, 10, ...) work on the stack with no heap allocation;
// N = Eigen::Dynamic allocates in start(), never in step().

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <utility>

#include "numlab/linalg/gauss_elimination_kernel.hpp"
#include "numlab/linalg/input_checks.hpp"
#include "numlab/linalg/linear_result.hpp"
#include "numlab/solver.hpp"

namespace numlab::linalg {

enum class Pivoting { partial, none };

enum class EliminationEvent { row_swap, elimination, back_substitution };

// What one step did: sent to an observer, if one is attached.
struct EliminationRecord {
  EliminationEvent event;
  int column;     // pivot column (swap, elimination) or the unknown just found (back substitution)
  int other_row;  // the row swapped with `column` (row_swap only)
  double value;   // the pivot used (row_swap, elimination) or the unknown's value (back substitution)
};

struct GaussEliminationOptions {
  Pivoting pivoting = Pivoting::partial;
  // A pivot is negligible when |pivot| <= relative_pivot_tolerance * max|a_ij|.
  // Unset means n * machine epsilon.
  std::optional<double> relative_pivot_tolerance;
};

template <int N = Eigen::Dynamic>
class GaussElimination {
 public:
  using MatrixType = Matrix<N>;
  using VectorType = Vector<N>;
  // Row-major, so that the elimination's inner loop runs along contiguous memory.
  using WorkMatrix = Eigen::Matrix<double, N, N, (N == 1 ? Eigen::ColMajor : Eigen::RowMajor)>;
  using Observer = StepObserver<GaussElimination<N>, EliminationRecord>;
  using PivotRows = Eigen::Matrix<int, N, 1>;
  using Permutation = Eigen::PermutationMatrix<N, N, int>;

  enum class Phase { elimination, back_substitution, done };

  explicit GaussElimination(GaussEliminationOptions options = {}) : options_(options) {
    if (options_.relative_pivot_tolerance) {
      require_non_negative(*options_.relative_pivot_tolerance, "relative pivot tolerance");
    }
  }

  // Receives every step (a swap and an elimination per column, then each unknown); null: none.
  void set_observer(Observer* observer) { observer_ = observer; }

  // Copies A and b, for stepping; throws std::invalid_argument on bad input.
  void start(const MatrixType& A, const VectorType& b) {
    load(A, b);
    prepare_stepping();
    original_matrix_ = A;
    original_rhs_ = b;
  }

  // Performs one pivot column or one back substitution. Returns false once the solve is over.
  bool step() {
    if (phase_ == Phase::elimination) {
      eliminate_next_column();
    } else if (phase_ == Phase::back_substitution) {
      back_substitute_next_unknown();
    }
    if (stop_requested_ && running()) {  // the observer ended the run: no verdict
      phase_ = Phase::done;
      stopped_ = true;
    }
    return running();
  }

  // The whole solve: step by step when an observer is attached, otherwise by the fast path (the
  // same x, status, growth factor and pivot columns). No copies of A and b are kept.
  LinearResult<N> solve(const MatrixType& A, const VectorType& b) {
    load(A, b);
    run();
    return result_for(A, b);
  }

  // For a caller that has already checked A and b are finite (Newton's inner solve): the same
  // elimination and x, without the input screens, the growth factor or the residual (not computed).
  LinearResult<N> solve_prechecked(const MatrixType& A, const VectorType& b) {
    load_unchecked(A, b);
    diagnostics_ = false;
    run();
    return result_for(A, b);
  }

  // The result of a solve begun with start().
  LinearResult<N> result() const { return result_for(original_matrix_, original_rhs_); }

  // The contract (numlab/solver.hpp).
  bool running() const { return phase_ != Phase::done; }
  Status status() const { return status_; }
  bool stopped() const { return stopped_; }
  int iterations() const { return column_; }  // pivot columns eliminated so far
  // Entries next_unknown()+1 ... n-1 are known during back substitution; all of them once converged.
  const VectorType& x() const { return x_; }

  // State between steps, for tracing and step-by-step labs.
  Phase phase() const { return phase_; }
  int size() const { return n_; }
  // While stepping, zeros below the diagonal; after the fast path, the multipliers sit there.
  const WorkMatrix& reduced_matrix() const { return reduced_; }
  const VectorType& reduced_rhs() const { return rhs_; }
  int next_unknown() const { return next_unknown_; }
  double growth_factor() const { return growth_factor_; }
  double negligible_pivot() const { return negligible_pivot_; }

  // The factors, P A = L R: after every pivot column, R the reduced matrix; P A = L U once factored().
  bool factored() const { return n_ > 0 && column_ == n_; }
  // L: unit lower triangular, column k holding the multipliers l_ik of the columns eliminated so far.
  MatrixType lower() const {
    MatrixType L = MatrixType::Identity(n_, n_);
    const WorkMatrix& kept = factors_in_place_ ? reduced_ : multipliers_;
    for (int i = 1; i < n_; ++i) {
      for (int j = 0; j < std::min(i, column_); ++j) L(i, j) = kept(i, j);
    }
    return L;
  }
  // R: the rows of U found so far and, below them, the block still to eliminate; U once factored().
  MatrixType upper() const {
    MatrixType R = reduced_;
    if (factors_in_place_) {
      for (int i = 1; i < n_; ++i) {
        for (int j = 0; j < std::min(i, column_); ++j) R(i, j) = 0.0;
      }
    }
    return R;
  }
  // P: the row swaps of step 2, in order (as Eigen's PartialPivLU::permutationP(), P A = L U).
  Permutation permutation() const {
    Permutation P;
    P.setIdentity(n_);
    for (int k = n_ - 1; k >= 0; --k) P.applyTranspositionOnTheRight(k, pivot_rows_(k));
    return P;
  }
  // The row swapped with row k at column k (k itself when none), for every column reached.
  const PivotRows& pivot_rows() const { return pivot_rows_; }

  // Solves A x = b for another b with the kept factors; throws std::logic_error unless factored().
  // Bit for bit the x of a fresh solve(A, b); its residual is not computed (A is not kept).
  LinearResult<N> solve_with_factors(const VectorType& b) const {
    if (!factored()) throw std::logic_error("solve_with_factors: no factorization kept (the last solve did not finish it)");
    if (b.size() != n_) throw std::invalid_argument("solve_with_factors: right-hand side of the wrong size");
    const WorkMatrix& kept = factors_in_place_ ? reduced_ : multipliers_;
    VectorType c = b;
    // P b: step 2's swaps, in order.
    for (int k = 0; k < n_; ++k) std::swap(c(k), c(pivot_rows_(k)));
    // Step 3 on b alone: c_i -= l_ik c_k, column by column.
    for (int k = 0; k < n_; ++k) {
      for (int i = k + 1; i < n_; ++i) c(i) -= kept(i, k) * c(k);
    }
    // Step 4: back substitution with U and the kept 1/u_ii.
    LinearResult<N> result;
    result.iterations = n_;
    result.growth_factor = growth_factor_;
    result.x.setZero(n_);
    result.status = Status::converged;
    for (int i = n_ - 1; i >= 0; --i) {
      result.x(i) = c(i) * inverse_pivots_(i);
      for (int j = 0; j < i; ++j) c(j) -= reduced_(j, i) * result.x(i);
      if (!std::isfinite(result.x(i))) {
        result.status = Status::non_finite;
        result.x.setConstant(n_, std::numeric_limits<double>::quiet_NaN());
        break;
      }
    }
    return result;
  }

 private:
  // Checks the input and sets up the working copies: reduced = A, rhs = b.
  void load(const MatrixType& A, const VectorType& b) {
    require_valid_system(A, b);
    load_unchecked(A, b);
    diagnostics_ = true;
  }

  void load_unchecked(const MatrixType& A, const VectorType& b) {
    matrix_max_ = A.cwiseAbs().maxCoeff();
    n_ = static_cast<int>(A.rows());
    reduced_ = A;
    rhs_ = b;
    x_.setZero(n_);
    pivot_rows_.setLinSpaced(n_, 0, n_ - 1);
    factors_in_place_ = true;
    inverse_pivots_.resize(n_);  // each entry is written in step 3 before step 4 reads it
    const double tolerance = options_.relative_pivot_tolerance.value_or(n_ * std::numeric_limits<double>::epsilon());
    negligible_pivot_ = tolerance * matrix_max_;
    column_ = 0;
    next_unknown_ = n_ - 1;
    growth_factor_ = LinearResult<N>::not_applicable;
    status_ = Status::running;
    phase_ = Phase::elimination;
    stop_requested_ = false;
    stopped_ = false;
  }

  // The stepper keeps the multipliers apart from the reduced matrix, which it shows with zeros below
  // the diagonal (the fast path keeps them in place, below U).
  void prepare_stepping() {
    multipliers_.setZero(n_, n_);
    factors_in_place_ = false;
  }

  // Steps to the end, or (no observer to show the steps to) the fast path to the same end.
  void run() {
    if (observer_ != nullptr) {
      prepare_stepping();
      while (step()) {
      }
      return;
    }
    const EliminationOutcome outcome = gepp_kernel<N>(reduced_, rhs_, inverse_pivots_, pivot_rows_, x_, negligible_pivot_,
                                                      options_.pivoting == Pivoting::partial);
    column_ = outcome.columns;
    next_unknown_ = -1;
    if (column_ == n_) record_growth_factor();
    finish(outcome.status);
  }

  LinearResult<N> result_for(const MatrixType& A, const VectorType& b) const {
    LinearResult<N> result;
    result.status = status_;
    result.iterations = column_;
    result.growth_factor = growth_factor_;
    if (status_ == Status::converged) {
      result.x = x_;
      if (diagnostics_) result.residual_norm = residual_inf_norm(A, b, x_);
    } else {
      // No solution exists to report: say so with NaN rather than print a meaningless number.
      result.x.setConstant(n_, std::numeric_limits<double>::quiet_NaN());
    }
    return result;
  }

  void eliminate_next_column() {
    const int k = column_;

    // 1. Find the pivot: the row p >= k with the largest |a_pk| (the first one, on a tie).
    int p = k;
    if (options_.pivoting == Pivoting::partial) {
      double largest = std::abs(reduced_(k, k));
      for (int i = k + 1; i < n_; ++i) {
        if (std::abs(reduced_(i, k)) > largest) {
          largest = std::abs(reduced_(i, k));
          p = i;
        }
      }
    }

    // 2. Swap rows k and p of A and b (and of the multipliers kept), bringing the pivot to the diagonal.
    pivot_rows_(k) = p;
    if (p != k) {
      reduced_.row(k).swap(reduced_.row(p));
      multipliers_.row(k).swap(multipliers_.row(p));
      std::swap(rhs_(k), rhs_(p));
      notify({EliminationEvent::row_swap, k, p, reduced_(k, k)});
      if (stop_requested_) return;  // the observer ended the run after the swap
    }

    // A pivot that is not finite, or negligible beside max|a_ij|, ends the solve: no division by it.
    const double pivot = reduced_(k, k);
    if (!std::isfinite(pivot)) {
      finish(Status::non_finite);
      return;
    }
    if (std::abs(pivot) <= negligible_pivot_) {
      finish(Status::singular);
      return;
    }

    // 3. Eliminate: row_i -= l_ik * row_k for each row i below, l_ik = a_ik / a_kk, so a_ik becomes 0;
    //    l_ik is kept in L.
    const double inverse_pivot = 1.0 / pivot;  // kept: back substitution multiplies by it
    inverse_pivots_(k) = inverse_pivot;
    for (int i = k + 1; i < n_; ++i) {
      const double multiplier = reduced_(i, k) * inverse_pivot;
      reduced_(i, k) = 0.0;
      multipliers_(i, k) = multiplier;
      for (int j = k + 1; j < n_; ++j) reduced_(i, j) -= multiplier * reduced_(k, j);
      rhs_(i) -= multiplier * rhs_(k);
    }
    ++column_;
    notify({EliminationEvent::elimination, k, k, pivot});

    if (column_ == n_) {
      record_growth_factor();
      phase_ = Phase::back_substitution;
    }
  }

  void back_substitute_next_unknown() {
    // 4. Back-substitute, column by column: x_i = c_i / u_ii, then c_j -= u_ji x_i for every row j
    //    above, so that c_j holds c_j - sum_{l>j} u_jl x_l by the time x_j is needed.
    const int i = next_unknown_;
    x_(i) = rhs_(i) * inverse_pivots_(i);
    for (int j = 0; j < i; ++j) rhs_(j) -= reduced_(j, i) * x_(i);
    --next_unknown_;
    notify({EliminationEvent::back_substitution, i, i, x_(i)});

    if (!std::isfinite(x_(i))) {
      finish(Status::non_finite);
    } else if (next_unknown_ < 0) {
      finish(Status::converged);
    }
  }

  // max|u_ij| / max|a_ij|, over U's upper triangle (below it: zeros, or the fast path's multipliers).
  void record_growth_factor() {
    if (!diagnostics_) return;
    double largest = 0.0;
    for (int i = 0; i < n_; ++i) largest = std::max(largest, reduced_.row(i).tail(n_ - i).cwiseAbs().maxCoeff());
    growth_factor_ = largest / matrix_max_;
  }

  void finish(Status status) {
    status_ = status;
    phase_ = Phase::done;
  }

  void notify(const EliminationRecord& record) {
    if (observer_ != nullptr && observer_->on_step(*this, record) == StepControl::stop) stop_requested_ = true;
  }

  GaussEliminationOptions options_;
  Observer* observer_ = nullptr;
  int n_ = 0;
  MatrixType original_matrix_ = zero_or_empty<MatrixType>();  // kept by start() for result()
  VectorType original_rhs_ = zero_or_empty<VectorType>();
  WorkMatrix reduced_ = zero_or_empty<WorkMatrix>();        // A, reduced step by step to U
  VectorType rhs_ = zero_or_empty<VectorType>();            // b, with the same row operations
  VectorType inverse_pivots_ = zero_or_empty<VectorType>(); // 1 / u_kk, once per column
  WorkMatrix multipliers_ = zero_or_empty<WorkMatrix>();    // L's l_ik, when stepping
  PivotRows pivot_rows_ = PivotRows::Zero(N == Eigen::Dynamic ? 0 : N);  // step 2's swaps
  bool factors_in_place_ = true;  // the multipliers below U in reduced_ (fast path), or in multipliers_
  VectorType x_ = zero_or_empty<VectorType>();
  double matrix_max_ = 0.0;
  double negligible_pivot_ = 0.0;
  int column_ = 0;
  int next_unknown_ = -1;
  double growth_factor_ = LinearResult<N>::not_applicable;
  bool diagnostics_ = true;  // growth factor and residual wanted (not by solve_prechecked)
  Status status_ = Status::running;
  Phase phase_ = Phase::done;
  bool stop_requested_ = false;  // the observer said stop during this step
  bool stopped_ = false;
};

// Convenience: one GEPP solve of A x = b.
template <int N>
LinearResult<N> gauss_elimination(const Matrix<N>& A, const Vector<N>& b, GaussEliminationOptions options = {}) {
  return GaussElimination<N>(options).solve(A, b);
}

}  // namespace numlab::linalg
