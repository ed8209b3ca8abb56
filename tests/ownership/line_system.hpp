#pragma once
// The system every ownership probe hands over: f(x) = x - 1, one unknown.

#include "numlab/nonlinear/system.hpp"

namespace numlab::ownership {

struct Line {
  static constexpr int size = 1;
  int dimension() const { return 1; }
  void residual(const nonlinear::Vector<1>& x, nonlinear::Vector<1>& f) const { f(0) = x(0) - 1.0; }
  void jacobian(const nonlinear::Vector<1>&, nonlinear::Matrix<1>& J) const { J(0, 0) = 1.0; }
};

}  // namespace numlab::ownership
