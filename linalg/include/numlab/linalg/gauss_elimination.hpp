#pragma once
// Gaussian elimination with partial pivoting (GEPP): seed 001's gauss_elim, done properly.
//
// For each column k:
//   1. pivot search  - find the row p >= k with the largest |a_pk|;
//   2. row swap      - exchange rows k and p (of A and b);
//   3. elimination   - for every row i below k: l_ik = a_ik / a_kk, row_i -= l_ik * row_k.
// Then:
//   4. back substitution - x_i = (c_i - sum_{j>i} u_ij x_j) / u_ii, from the last unknown up,
//                          column by column (each x_i is subtracted from the c_j above it at once),
//                          multiplying by the 1/u_ii kept from step 3.
//
// A pivot that is zero relative to the matrix's scale (|a_kk| <= tol * max|a_ij|, tol = n*eps by
// default) ends the solve with Status::singular: there is never a division by a negligible pivot.
// The growth factor max|u_ij| / max|a_ij| is reported; it bounds how much rounding error the
// elimination can amplify (2^(n-1) at worst, reached by Wilkinson's matrix).
//
// One step() is one pivot column (steps 1-3) or one back-substituted unknown. Fixed sizes
// (N = 2, 8, 10, ...) work on the stack with no heap allocation; N = Eigen::Dynamic allocates
// in start(), never in step().

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "numlab/linalg/input_checks.hpp"
#include "numlab/linalg/linear_result.hpp"

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

template <int N>
class GaussElimination;

template <int N>
class GaussEliminationObserver {
 public:
  virtual ~GaussEliminationObserver() = default;
  virtual void on_step(const GaussElimination<N>& state, const EliminationRecord& record) = 0;
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

  enum class Phase { elimination, back_substitution, done };

  explicit GaussElimination(GaussEliminationOptions options = {}) : options_(options) {
    if (options_.relative_pivot_tolerance) {
      require_non_negative(*options_.relative_pivot_tolerance, "relative pivot tolerance");
    }
  }

  void set_observer(GaussEliminationObserver<N>* observer) { observer_ = observer; }

  // Copies A and b, for stepping; throws std::invalid_argument on bad input.
  void start(const MatrixType& A, const VectorType& b) {
    load(A, b);
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
    return phase_ != Phase::done;
  }

  // start(), step() until done, result(); without the copies of A and b that stepping keeps.
  LinearResult<N> solve(const MatrixType& A, const VectorType& b) {
    load(A, b);
    while (step()) {
    }
    return result_for(A, b);
  }

  // For a caller that has already checked A and b are finite (Newton's inner solve): the same
  // elimination and x, without the input screens, the growth factor or the residual (not computed).
  LinearResult<N> solve_prechecked(const MatrixType& A, const VectorType& b) {
    load_unchecked(A, b);
    diagnostics_ = false;
    while (step()) {
    }
    return result_for(A, b);
  }

  // The result of a solve begun with start().
  LinearResult<N> result() const { return result_for(original_matrix_, original_rhs_); }

  // State between steps, for tracing and step-by-step labs.
  Phase phase() const { return phase_; }
  Status status() const { return status_; }
  int size() const { return n_; }
  int columns_eliminated() const { return column_; }
  const WorkMatrix& reduced_matrix() const { return reduced_; }
  const VectorType& reduced_rhs() const { return rhs_; }
  // Entries next_unknown()+1 ... n-1 of solution() are known during back substitution.
  const VectorType& solution() const { return x_; }
  int next_unknown() const { return next_unknown_; }
  double growth_factor() const { return growth_factor_; }
  double negligible_pivot() const { return negligible_pivot_; }

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
    inverse_pivots_.resize(n_);  // each entry is written in step 3 before step 4 reads it
    const double tolerance = options_.relative_pivot_tolerance.value_or(n_ * std::numeric_limits<double>::epsilon());
    negligible_pivot_ = tolerance * matrix_max_;
    column_ = 0;
    next_unknown_ = n_ - 1;
    growth_factor_ = LinearResult<N>::not_applicable;
    status_ = Status::converged;
    phase_ = Phase::elimination;
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
    const int n = dimension();

    // 1. Pivot search: the largest |a_ik| on or below the diagonal (the first, on a tie).
    int pivot_row = k;
    if (options_.pivoting == Pivoting::partial) {
      double largest = std::abs(reduced_(k, k));
      for (int i = k + 1; i < n; ++i) {
        const double candidate = std::abs(reduced_(i, k));
        const bool larger = candidate > largest;  // selects without a branch to mispredict
        largest = larger ? candidate : largest;
        pivot_row = larger ? i : pivot_row;
      }
    }

    // 2. Row swap: bring the pivot to the diagonal. The pivot's row is found by comparing it with
    //    each row index, not used as an index: the processor predicts a comparison and starts the
    //    swap at once, where an index computed by the search would hold the swap until the search
    //    is done (Newton's Jacobians pivot alike from one solve to the next; 8x8 Jansen solves took
    //    20% less time). No `break` after the swap: with one, the compiler sees that the loop ends
    //    at i == pivot_row and indexes by pivot_row again (measured: the full Jansen row 0.124 ->
    //    0.146 ms per cycle).
    for (int i = k + 1; i < n && pivot_row != k; ++i) {
      if (i != pivot_row) continue;
      reduced_.row(k).swap(reduced_.row(i));
      std::swap(rhs_(k), rhs_(i));
      notify({EliminationEvent::row_swap, k, i, reduced_(k, k)});
    }

    const double pivot = reduced_(k, k);
    if (!std::isfinite(pivot)) {
      finish(Status::non_finite);
      return;
    }
    if (std::abs(pivot) <= negligible_pivot_) {
      finish(Status::singular);
      return;
    }

    // 3. Elimination: subtract l_ik * (row k) from each row i below, so that a_ik becomes 0.
    const double inverse_pivot = 1.0 / pivot;  // kept: back substitution multiplies by it
    inverse_pivots_(k) = inverse_pivot;
    const double* pivot_row_entries = row_pointer(k);
    for (int i = k + 1; i < n; ++i) {
      double* row = row_pointer(i);
      const double multiplier = row[k] * inverse_pivot;  // l_ik = a_ik / a_kk
      row[k] = 0.0;
      for (int j = k + 1; j < n; ++j) row[j] -= multiplier * pivot_row_entries[j];
      rhs_(i) -= multiplier * rhs_(k);
    }
    ++column_;
    notify({EliminationEvent::elimination, k, k, pivot});

    if (column_ == n) {
      // Every entry below the diagonal was set to exactly 0 when its column was eliminated, so
      // max|u_ij| is the largest entry of the whole working matrix.
      if (diagnostics_) growth_factor_ = reduced_.cwiseAbs().maxCoeff() / matrix_max_;
      phase_ = Phase::back_substitution;
    }
  }

  void back_substitute_next_unknown() {
    // 4. Back substitution, column by column: x_i = c_i / u_ii, then c_j -= u_ji x_i for every
    //    row j above, so that c_j holds c_j - sum_{l>j} u_jl x_l by the time x_j is needed.
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

  // The size n: a compile-time constant for fixed sizes, so their loops have known bounds.
  int dimension() const { return N == Eigen::Dynamic ? n_ : N; }

  // Row i of the working matrix as plain memory (row-major, so its entries are contiguous).
  double* row_pointer(int i) { return reduced_.data() + static_cast<Eigen::Index>(i) * dimension(); }
  const double* row_pointer(int i) const { return reduced_.data() + static_cast<Eigen::Index>(i) * dimension(); }

  void finish(Status status) {
    status_ = status;
    phase_ = Phase::done;
  }

  void notify(const EliminationRecord& record) {
    if (observer_ != nullptr) observer_->on_step(*this, record);
  }

  GaussEliminationOptions options_;
  GaussEliminationObserver<N>* observer_ = nullptr;
  int n_ = 0;
  MatrixType original_matrix_ = zero_or_empty<MatrixType>();  // kept by start() for result()
  VectorType original_rhs_ = zero_or_empty<VectorType>();
  WorkMatrix reduced_ = zero_or_empty<WorkMatrix>();        // A, reduced step by step to U
  VectorType rhs_ = zero_or_empty<VectorType>();            // b, with the same row operations
  VectorType inverse_pivots_ = zero_or_empty<VectorType>(); // 1 / u_kk, once per column
  VectorType x_ = zero_or_empty<VectorType>();
  double matrix_max_ = 0.0;
  double negligible_pivot_ = 0.0;
  int column_ = 0;
  int next_unknown_ = -1;
  double growth_factor_ = LinearResult<N>::not_applicable;
  bool diagnostics_ = true;  // growth factor and residual wanted (not by solve_prechecked)
  Status status_ = Status::converged;
  Phase phase_ = Phase::done;
};

// Convenience: one GEPP solve of A x = b.
template <int N>
LinearResult<N> gauss_elimination(const Matrix<N>& A, const Vector<N>& b, GaussEliminationOptions options = {}) {
  return GaussElimination<N>(options).solve(A, b);
}

}  // namespace numlab::linalg
