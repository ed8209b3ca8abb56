#pragma once
// The fast path of GaussElimination::solve() and solve_prechecked(): the GEPP of
// gauss_elimination.hpp as one loop, with no observer and no stepping state. It performs the same
// operations in the same order (the multiplier a_ik * (1/pivot), the same row updates, back
// substitution column by column times the kept 1/pivot), so x, the status and the pivot columns
// are bit for bit those of the textbook stepper: tests/linalg/test_gepp_paths.cpp and
// tests/mechanisms/test_gepp_paths.cpp check it. A student reads gauss_elimination.hpp, not this.

#include <Eigen/Core>
#include <cmath>
#include <utility>

#include "numlab/status.hpp"

namespace numlab::linalg {

// How the fast path ended: the verdict and the pivot columns eliminated.
struct EliminationOutcome {
  Status status;
  int columns;
};

// Solves the system held in U (row-major, n x n) and c in place: U's upper triangle becomes U, its
// strictly lower part keeps the multipliers l_ik (LAPACK's packed LU, moved with their rows by
// later swaps), pivot_rows[k] = the row swapped with row k, inverse_pivots[k] = 1/u_kk, and x the
// solution. A pivot with |u_kk| <= negligible_pivot stops it with Status::singular, a non-finite
// pivot or unknown with Status::non_finite.
template <int N, typename WorkMatrix, typename VectorType, typename PivotRows>
EliminationOutcome gepp_kernel(WorkMatrix& U, VectorType& c, VectorType& inverse_pivots, PivotRows& pivot_rows,
                               VectorType& x, double negligible_pivot, bool partial_pivoting) {
  const int n = N == Eigen::Dynamic ? static_cast<int>(U.rows()) : N;
  // Differs from the textbook: rows as raw pointers (row-major, so each row is contiguous).
  double* const rows = U.data();
  const auto row = [rows, stride = static_cast<Eigen::Index>(n)](int i) { return rows + static_cast<Eigen::Index>(i) * stride; };

  for (int k = 0; k < n; ++k) {
    int pivot_row = k;
    if (partial_pivoting) {
      double largest = std::abs(row(k)[k]);
      for (int i = k + 1; i < n; ++i) {
        const double candidate = std::abs(row(i)[k]);
        if (candidate > largest) {
          largest = candidate;
          pivot_row = i;
        }
      }
    }

    // Differs from the textbook: the swap is found by comparing indices (no break), not by indexing.
    for (int i = k + 1; i < n && pivot_row != k; ++i) {
      if (i != pivot_row) continue;
      U.row(k).swap(U.row(i));
      std::swap(c(k), c(i));
    }
    pivot_rows(k) = pivot_row;

    const double pivot = row(k)[k];
    if (!std::isfinite(pivot)) return {Status::non_finite, k};
    if (std::abs(pivot) <= negligible_pivot) return {Status::singular, k};

    const double inverse_pivot = 1.0 / pivot;
    inverse_pivots(k) = inverse_pivot;
    const double* pivot_entries = row(k);
    for (int i = k + 1; i < n; ++i) {
      double* entries = row(i);
      const double multiplier = entries[k] * inverse_pivot;
      entries[k] = multiplier;  // kept for L (the textbook sets a_ik to 0 and keeps l_ik apart)
      for (int j = k + 1; j < n; ++j) entries[j] -= multiplier * pivot_entries[j];
      c(i) -= multiplier * c(k);
    }
  }

  for (int i = n - 1; i >= 0; --i) {
    x(i) = c(i) * inverse_pivots(i);
    for (int j = 0; j < i; ++j) c(j) -= row(j)[i] * x(i);
    if (!std::isfinite(x(i))) return {Status::non_finite, n};
  }
  return {Status::converged, n};
}

}  // namespace numlab::linalg
