#pragma once
// How far a solved pose may honestly be from the closed form, given its residual and conditioning.
//
// A pose x with residual f(x) is within ||dx||_inf <= ||J^-1||_inf ||f||_inf of the exact angles
// (to first order), and a joint is a sum of links l_k u(theta_k), so it moves at most
// (sum of the links) ||dx||_inf. With a factor 2 for the second-order terms and rounding
// (1e3 eps of the links' sum, the closed form's own included):
//
//   bound = 2 L ||J^-1||_inf ||f||_inf + 1e3 eps L,      L = the sum of the link lengths.
//
// The rule every sweep applies (docs/mechanisms.md): a pose is verified when its distance from the
// closed form is within its bound and the bound is below half the shortest link. Then the angles
// are within ||J^-1|| ||f|| = bound / 2L <= l_min / 4L of exact (under 0.01 rad for both linkages),
// where the first-order picture holds (the second-order term is under 1% of the first), and the
// other branch is about a link's length away. Beyond it the residual justifies nothing. A sweep is
// converged, and its branch kept, only when every pose is verified.

#include <Eigen/LU>
#include <cmath>
#include <limits>

namespace numlab::mechanisms {

struct ClosedFormBound {
  double residual_norm = 0.0;  // ||f||_inf at the pose, evaluated again
  double bound = 0.0;          // the distance from the closed form that the residual justifies
};

// Closure: a fixed-size system (set to the pose's crank angle) with residual_and_jacobian().
template <typename Closure>
ClosedFormBound closed_form_bound(const Closure& closure, const typename Closure::Vector& x, double links_sum) {
  typename Closure::Vector f;
  typename Closure::Matrix J;
  closure.residual_and_jacobian(x, f, J);
  const Eigen::PartialPivLU<typename Closure::Matrix> lu(J);
  const double inverse_norm = lu.inverse().cwiseAbs().rowwise().sum().maxCoeff();
  ClosedFormBound result;
  result.residual_norm = f.template lpNorm<Eigen::Infinity>();
  const double rounding = 1e3 * std::numeric_limits<double>::epsilon() * links_sum;
  result.bound = 2.0 * links_sum * inverse_norm * result.residual_norm + rounding;
  if (!std::isfinite(result.bound)) result.bound = std::numeric_limits<double>::infinity();
  return result;
}

// The rule above, for one pose.
inline bool closed_form_verified(double distance, double bound, double shortest_link) {
  return distance <= bound && bound <= 0.5 * shortest_link;
}

}  // namespace numlab::mechanisms
