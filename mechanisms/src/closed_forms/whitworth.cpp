// The Whitworth quick-return in closed form (closed_forms/whitworth.hpp).

#include "numlab/mechanisms/closed_forms/whitworth.hpp"

#include "numlab/mechanisms/closed_forms/inverted_slider_crank.hpp"

#include <cmath>
#include <stdexcept>

namespace numlab::mechanisms::closed_forms {

WhitworthPose whitworth(const Whitworth& m, double t) {
  WhitworthPose pose;
  // 1.-3. The crank, the slotted link and its end B: an inverted slider-crank O2-A in the slot O4-B.
  const InvertedSliderCrankPose driving = inverted_slider_crank({m.O2, m.O4, m.crank, m.slot}, t);
  pose.crank = driving.crank;
  pose.A = driving.A;
  pose.slot = driving.rocker;
  pose.slide = driving.slide;
  pose.B = driving.C;
  // 4. The ram, on the line y = h at the rod's length from B.
  const double side = m.ram_side >= 0 ? 1.0 : -1.0;
  const double w = m.ram_height - pose.B.p.y(), dw = -pose.B.v.y(), ddw = -pose.B.a.y();
  const double q = std::sqrt(m.rod * m.rod - w * w);
  const double dq = -w * dw / q;
  const double ddq = -(dw * dw + w * ddw) / q - w * w * dw * dw / (q * q * q);
  pose.C.p = {pose.B.p.x() + side * q, m.ram_height};
  pose.C.v = {pose.B.v.x() + side * dq, 0.0};
  pose.C.a = {pose.B.a.x() + side * ddq, 0.0};
  // 5. The rod's angle.
  pose.rod = {std::atan2(w, side * q), side * dw / q, side * (ddw * q - dw * dq) / (q * q)};
  return pose;
}

QuickReturn whitworth_quick_return(const Whitworth& m) {
  if (m.ram_height != m.O4.y()) throw std::invalid_argument("whitworth_quick_return: the ram's line must pass through O4");
  const double k = (m.O4.y() - m.O2.y()) / m.crank;
  const double beta = std::asin(std::abs(k));
  return {in_one_turn(std::asin(k)), in_one_turn(pi - std::asin(k)), (pi + 2.0 * beta) / (pi - 2.0 * beta)};
}

}  // namespace numlab::mechanisms::closed_forms
