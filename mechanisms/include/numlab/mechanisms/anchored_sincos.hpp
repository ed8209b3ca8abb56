#pragma once
// Cosines and sines of angles that move only a little from one evaluation to the next, as
// Newton's iterates and a crank sweep's poses do.
//
// Each angle keeps an anchor a, where std::cos and std::sin were last called. An angle t = a + d
// with |d| <= 1/8 is reached from it by the angle-addition formulas
//   cos t = cos a + (cos a (cos d - 1) - sin a sin d),
//   sin t = sin a + (sin a (cos d - 1) + cos a sin d),
// with sin d and cos d - 1 from their Taylor series (the first omitted terms, d^11/11! and
// d^12/12!, are below 3e-18: a fortieth of an ulp of the result). Farther away, t becomes the
// angle's new anchor. The angle last reached from its anchor is kept too ("recent"): a Newton
// correction away from it (|h| <= 2^-20) needs only sin h = h and cos h - 1 = -h^2/2 (the next
// terms are below 2e-19). So every value is at most two such steps from a library value and
// nothing drifts: results agree with std::cos and std::sin to a few units in the last place.
// Non-finite angles go to the library.

#include <Eigen/Core>
#include <cmath>
#include <limits>

#include "numlab/linalg/linear_result.hpp"

namespace numlab::mechanisms {

template <int N>
class AnchoredSinCos {
 public:
  static constexpr double largest_offset = 1.0 / 8.0;
  static constexpr double largest_correction = 0x1p-20;

  // c_k = cos theta_k and s_k = sin theta_k for every k.
  [[gnu::always_inline]] void evaluate(const linalg::Vector<N>& theta, linalg::Vector<N>& c, linalg::Vector<N>& s) {
    for (int k = 0; k < N; ++k) {
      const double t = theta(k);
      // 1. A Newton correction h from the recent angle: rotate its values by h.
      const double h = t - recent_(k);
      if (std::abs(h) <= largest_correction) {
        const double cos_h_minus_1 = -0.5 * h * h;
        c(k) = recent_cos_(k) + (recent_cos_(k) * cos_h_minus_1 - recent_sin_(k) * h);
        s(k) = recent_sin_(k) + (recent_sin_(k) * cos_h_minus_1 + recent_cos_(k) * h);
        continue;
      }
      const double d = t - anchor_(k);
      if (std::abs(d) <= largest_offset) {
        // 2. Near the anchor: sin d and cos d - 1 by Horner's rule on their Taylor series, then
        //    rotate the anchor's values by d, the small correction added last.
        const double d2 = d * d;
        const double sin_d = d + d * d2 * (-1.0 / 6 + d2 * (1.0 / 120 + d2 * (-1.0 / 5040 + d2 * (1.0 / 362880))));
        const double cos_d_minus_1 =
            d2 * (-1.0 / 2 + d2 * (1.0 / 24 + d2 * (-1.0 / 720 + d2 * (1.0 / 40320 + d2 * (-1.0 / 3628800)))));
        c(k) = anchor_cos_(k) + (anchor_cos_(k) * cos_d_minus_1 - anchor_sin_(k) * sin_d);
        s(k) = anchor_sin_(k) + (anchor_sin_(k) * cos_d_minus_1 + anchor_cos_(k) * sin_d);
      } else {
        // 3. Too far from the anchor (or no anchor yet, or t not finite): the library, and a new anchor.
        anchor_(k) = t;
        anchor_cos_(k) = std::cos(t);  // one argument for both: the compiler makes one sincos call
        anchor_sin_(k) = std::sin(t);
        c(k) = anchor_cos_(k);
        s(k) = anchor_sin_(k);
      }
      recent_(k) = t;
      recent_cos_(k) = c(k);
      recent_sin_(k) = s(k);
    }
  }

 private:
  using Angles = linalg::Vector<N>;
  static constexpr double no_angle = std::numeric_limits<double>::quiet_NaN();  // compares as far from all
  Angles anchor_ = Angles::Constant(no_angle), anchor_cos_ = Angles::Zero(), anchor_sin_ = Angles::Zero();
  Angles recent_ = Angles::Constant(no_angle), recent_cos_ = Angles::Zero(), recent_sin_ = Angles::Zero();
};

}  // namespace numlab::mechanisms
