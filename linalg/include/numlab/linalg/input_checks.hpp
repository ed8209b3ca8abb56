#pragma once
// Checks for misuse and bad input, shared by every linear method.
// Each throws std::invalid_argument with a message that names the offending value.

#include <Eigen/Core>
#include <cmath>
#include <stdexcept>
#include <string>

namespace numlab::linalg {

template <typename MatrixType>
void require_square(const MatrixType& A, const char* what) {
  if (A.rows() != A.cols() || A.rows() == 0) {
    throw std::invalid_argument(std::string(what) + " must be square and non-empty, got " +
                                std::to_string(A.rows()) + "x" + std::to_string(A.cols()));
  }
}

template <typename MatrixType, typename VectorType>
void require_matching_rhs(const MatrixType& A, const VectorType& b) {
  if (b.size() != A.rows()) {
    throw std::invalid_argument("right-hand side has " + std::to_string(b.size()) +
                                " entries but the matrix has " + std::to_string(A.rows()) + " rows");
  }
}

// True when every entry is finite: x * 0 is 0 for finite x and NaN for NaN or +-infinity, so
// the sum is 0 or NaN (it cannot overflow). Branch-free and vectorized, unlike an entry-wise test.
template <typename Derived>
bool all_finite(const Eigen::DenseBase<Derived>& values) {
  return (values.derived().array() * 0.0).sum() == 0.0;
}

template <typename Derived>
void require_finite(const Eigen::DenseBase<Derived>& values, const char* what) {
  // The vectorized screen first; the entry-by-entry scan only to name the bad entry.
  if (all_finite(values)) return;
  for (Eigen::Index j = 0; j < values.cols(); ++j) {
    for (Eigen::Index i = 0; i < values.rows(); ++i) {
      if (!std::isfinite(values(i, j))) {
        throw std::invalid_argument(std::string(what) + " has a non-finite entry (" +
                                    std::to_string(values(i, j)) + ") at row " + std::to_string(i + 1) +
                                    ", column " + std::to_string(j + 1));
      }
    }
  }
}

// The checks every solve(A, b) starts with.
template <typename MatrixType, typename VectorType>
void require_valid_system(const MatrixType& A, const VectorType& b) {
  require_square(A, "matrix");
  require_matching_rhs(A, b);
  require_finite(A, "matrix");
  require_finite(b, "right-hand side");
}

inline void require_non_negative(double value, const char* what) {
  if (!(value >= 0.0)) {
    throw std::invalid_argument(std::string(what) + " must be non-negative, got " + std::to_string(value));
  }
}

}  // namespace numlab::linalg
