#pragma once
// Cosines and sines of angles that move only a little from one evaluation to the next, as
// Newton's iterates and a crank sweep's poses do.
//
// Each angle keeps an anchor a, where std::cos and std::sin were last called. An angle t = a + d
// with |d| <= 1/16 is reached from it by the angle-addition formulas
//   cos t = cos a + (cos a (cos d - 1) - sin a sin d),
//   sin t = sin a + (sin a (cos d - 1) + cos a sin d),
// with sin d and cos d - 1 from their Taylor series (the first omitted terms, d^11/11! and
// d^12/12!, are below 1e-19 of the sums kept). Farther away, t becomes the angle's new anchor.
// Every value is one such step from a library value, so nothing drifts: results agree with
// std::cos and std::sin to a few units in the last place. Non-finite angles go to the library.

#include <Eigen/Core>
#include <cmath>
#include <limits>

#include "numlab/linalg/linear_result.hpp"

namespace numlab::mechanisms {

template <int N>
class AnchoredSinCos {
 public:
  static constexpr double largest_offset = 1.0 / 16.0;

  // c_k = cos theta_k and s_k = sin theta_k for every k.
  void evaluate(const linalg::Vector<N>& theta, linalg::Vector<N>& c, linalg::Vector<N>& s) {
    for (int k = 0; k < N; ++k) {
      const double t = theta(k), d = t - anchor_(k);
      // 1. Too far from the anchor (or no anchor yet): the library, and a new anchor.
      if (!(std::abs(d) <= largest_offset)) {
        anchor_(k) = t;
        anchor_cos_(k) = std::cos(t);  // one argument for both: the compiler makes one sincos call
        anchor_sin_(k) = std::sin(t);
        c(k) = anchor_cos_(k);
        s(k) = anchor_sin_(k);
        continue;
      }
      // 2. sin d and cos d - 1 by Horner's rule on their Taylor series.
      const double d2 = d * d;
      const double sin_d = d + d * d2 * (-1.0 / 6 + d2 * (1.0 / 120 + d2 * (-1.0 / 5040 + d2 * (1.0 / 362880))));
      const double cos_d_minus_1 =
          d2 * (-1.0 / 2 + d2 * (1.0 / 24 + d2 * (-1.0 / 720 + d2 * (1.0 / 40320 + d2 * (-1.0 / 3628800)))));
      // 3. Rotate the anchor's cosine and sine by d; the small correction is added last.
      c(k) = anchor_cos_(k) + (anchor_cos_(k) * cos_d_minus_1 - anchor_sin_(k) * sin_d);
      s(k) = anchor_sin_(k) + (anchor_sin_(k) * cos_d_minus_1 + anchor_cos_(k) * sin_d);
    }
  }

 private:
  using Angles = linalg::Vector<N>;
  Angles anchor_ = Angles::Constant(std::numeric_limits<double>::quiet_NaN());  // NaN: no anchor yet
  Angles anchor_cos_ = Angles::Zero(), anchor_sin_ = Angles::Zero();
};

}  // namespace numlab::mechanisms
