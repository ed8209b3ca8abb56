#pragma once
// What a nonlinear system f(x) = 0 looks like to numlab's solvers.
//
// A system is a small type with
//   static constexpr int size;                           // N, or Eigen::Dynamic
//   int dimension() const;                               // n (equal to N when fixed)
//   void residual(const Vector<N>& x, Vector<N>& f) const;
//   void jacobian(const Vector<N>& x, Matrix<N>& J) const;
// and, optionally,
//   void residual_and_jacobian(const Vector<N>& x, Vector<N>& f, Matrix<N>& J) const;
// which Newton prefers when present (so a model can share its sines and cosines between the two).

#include <Eigen/Core>
#include <concepts>

#include "numlab/linalg/linear_result.hpp"

namespace numlab::nonlinear {

using linalg::Matrix;
using linalg::Vector;

template <typename S>
concept NonlinearSystem = requires(const S& system, const Vector<S::size>& x, Vector<S::size>& f, Matrix<S::size>& J) {
  { S::size } -> std::convertible_to<int>;
  { system.dimension() } -> std::convertible_to<int>;
  system.residual(x, f);
  system.jacobian(x, J);
};

template <typename S>
concept SharesEvaluation = requires(const S& system, const Vector<S::size>& x, Vector<S::size>& f,
                                    Matrix<S::size>& J) { system.residual_and_jacobian(x, f, J); };

// For a system that computes f and J together: residual() and jacobian() from
// Derived::residual_and_jacobian(), each discarding the other half.
template <typename Derived, int N>
class EvaluatesTogether {
 public:
  void residual(const Vector<N>& x, Vector<N>& f) const {
    Matrix<N> unused = linalg::zero_or_empty<Matrix<N>>();
    static_cast<const Derived&>(*this).residual_and_jacobian(x, f, unused);
  }
  void jacobian(const Vector<N>& x, Matrix<N>& J) const {
    Vector<N> unused = linalg::zero_or_empty<Vector<N>>();
    static_cast<const Derived&>(*this).residual_and_jacobian(x, unused, J);
  }
};

// f(x) and J(x), in one call when the system offers it.
template <NonlinearSystem S>
void evaluate(const S& system, const Vector<S::size>& x, Vector<S::size>& f, Matrix<S::size>& J) {
  if constexpr (SharesEvaluation<S>) {
    system.residual_and_jacobian(x, f, J);
  } else {
    system.residual(x, f);
    system.jacobian(x, J);
  }
}

// A system whose size is only known at run time, behind a virtual interface: what the command
// line, the GSL adapter and the problem catalogue pass around.
class DynamicSystem {
 public:
  static constexpr int size = Eigen::Dynamic;
  virtual ~DynamicSystem() = default;
  virtual int dimension() const = 0;
  virtual void residual(const Eigen::VectorXd& x, Eigen::VectorXd& f) const = 0;
  virtual void jacobian(const Eigen::VectorXd& x, Eigen::MatrixXd& J) const = 0;
  // Both at once; systems that share work between f and J override it.
  virtual void residual_and_jacobian(const Eigen::VectorXd& x, Eigen::VectorXd& f, Eigen::MatrixXd& J) const {
    residual(x, f);
    jacobian(x, J);
  }
};

}  // namespace numlab::nonlinear
