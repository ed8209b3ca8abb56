#pragma once
// A fixed-size system seen through the DynamicSystem interface (for GSL, the sparsity pattern,
// the Jacobian check and generic sequential Newton). It copies between fixed and dynamic vectors,
// so the fixed-size Newton remains the fast path.

#include "numlab/nonlinear/system.hpp"

namespace numlab::nonlinear {

template <NonlinearSystem S>
class AsDynamicSystem final : public DynamicSystem {
 public:
  explicit AsDynamicSystem(const S& system) : system_(system) {}
  explicit AsDynamicSystem(const S&&) = delete;  // it keeps a reference: a temporary would dangle
  int dimension() const override { return system_.dimension(); }
  void residual(const Eigen::VectorXd& x, Eigen::VectorXd& f) const override {
    Vector<S::size> fixed_f;
    system_.residual(Vector<S::size>(x), fixed_f);
    f = fixed_f;
  }
  void jacobian(const Eigen::VectorXd& x, Eigen::MatrixXd& J) const override {
    Matrix<S::size> fixed_J;
    system_.jacobian(Vector<S::size>(x), fixed_J);
    J = fixed_J;
  }
  void residual_and_jacobian(const Eigen::VectorXd& x, Eigen::VectorXd& f, Eigen::MatrixXd& J) const override {
    Vector<S::size> fixed_f;
    Matrix<S::size> fixed_J;
    evaluate(system_, Vector<S::size>(x), fixed_f, fixed_J);  // shared work, when S offers it
    f = fixed_f;
    J = fixed_J;
  }

 private:
  const S& system_;
};

// The other way round: a DynamicSystem seen through Newton's compile-time interface, evaluating f
// and J separately (as the system's own residual() and jacobian() do).
struct DynamicReference {
  static constexpr int size = Eigen::Dynamic;
  const DynamicSystem& system;
  int dimension() const { return system.dimension(); }
  void residual(const Eigen::VectorXd& x, Eigen::VectorXd& f) const { system.residual(x, f); }
  void jacobian(const Eigen::VectorXd& x, Eigen::MatrixXd& J) const { system.jacobian(x, J); }
};

}  // namespace numlab::nonlinear
