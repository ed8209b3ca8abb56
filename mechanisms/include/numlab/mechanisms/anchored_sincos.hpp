#pragma once
// Cosines and sines of angles that move only a little from one evaluation to the next, as
// Newton's iterates and a crank sweep's poses do.
//
// An angle t is anchored at the nearest node a = k/64 of a table of std::cos and std::sin
// (|t| <= 32 rad; farther out, and for non-finite t, the library is called). With d = t - a
// (exact, |d| <= 1/128) the angle-addition formulas give
//   cos t = cos a + (cos a (cos d - 1) - sin a sin d),
//   sin t = sin a + (sin a (cos d - 1) + cos a sin d),
// with sin d and cos d - 1 from their Taylor series (the first omitted terms, d^7/7! and d^8/8!,
// are below 4e-19: a five-hundredth of an ulp of 1). The angle last reached that way is kept
// ("recent"): a Newton correction away from it (|h| <= 2^-20) needs only sin h = h and
// cos h - 1 = -h^2/2 (the next terms are below 2e-19). So every value is at most two such steps
// from a library value and nothing drifts: results agree with std::cos and std::sin to a few
// units in the last place.
//
// The table (64 KiB, filled on first use) replaced anchors kept per angle and moved to the
// angle whenever it strayed 1/8 rad away: that needed the series to d^10 and a library call
// every few poses. Measured on the Jansen crank cycle: sequential Newton 47.5 -> 44.8 us, full
// Newton 123 -> 116 us (best of repeated in-process runs).

#include <Eigen/Core>
#include <array>
#include <cmath>
#include <limits>

#include "numlab/linalg/linear_result.hpp"

namespace numlab::mechanisms {

// std::cos and std::sin at the nodes k/64, |k| <= reach.
struct SinCosNodes {
  static constexpr double per_radian = 64.0;
  static constexpr int reach = 2048;
  std::array<double, 2 * reach + 1> cos, sin;  // index k + reach
};

inline const SinCosNodes& sincos_nodes() {
  static const SinCosNodes nodes = [] {
    SinCosNodes table;
    for (int k = -SinCosNodes::reach; k <= SinCosNodes::reach; ++k) {
      const double node = k / SinCosNodes::per_radian;  // exact
      table.cos[k + SinCosNodes::reach] = std::cos(node);
      table.sin[k + SinCosNodes::reach] = std::sin(node);
    }
    return table;
  }();
  return nodes;
}

template <int N>
class AnchoredSinCos {
 public:
  static constexpr double largest_correction = 0x1p-20;
  static constexpr double table_limit = (SinCosNodes::reach - 1) / SinCosNodes::per_radian;  // |t| beyond: library

  // c_k = cos theta_k and s_k = sin theta_k for every k.
  [[gnu::always_inline]] void evaluate(const linalg::Vector<N>& theta, linalg::Vector<N>& c, linalg::Vector<N>& s) {
    const SinCosNodes& nodes = sincos_nodes();
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
      if (std::abs(t) <= table_limit) {
        // 2. The nearest node a = k/64 (adding and subtracting 1.5 * 2^52 rounds to an integer),
        //    sin d and cos d - 1 by Horner's rule, then rotate the node's values by d.
        constexpr double rounder = 0x1.8p52;
        const double nearest = (t * SinCosNodes::per_radian + rounder) - rounder;
        const int node = static_cast<int>(nearest) + SinCosNodes::reach;
        const double d = t - nearest / SinCosNodes::per_radian;
        const double d2 = d * d;
        const double sin_d = d + d * d2 * (-1.0 / 6 + d2 * (1.0 / 120));
        const double cos_d_minus_1 = d2 * (-1.0 / 2 + d2 * (1.0 / 24 + d2 * (-1.0 / 720)));
        const double cos_a = nodes.cos[node], sin_a = nodes.sin[node];
        c(k) = cos_a + (cos_a * cos_d_minus_1 - sin_a * sin_d);
        s(k) = sin_a + (sin_a * cos_d_minus_1 + cos_a * sin_d);
      } else {
        // 3. Beyond the table (or t not finite): the library.
        c(k) = std::cos(t);  // one argument for both: the compiler makes one sincos call
        s(k) = std::sin(t);
      }
      recent_(k) = t;
      recent_cos_(k) = c(k);
      recent_sin_(k) = s(k);
    }
  }

 private:
  using Angles = linalg::Vector<N>;
  static constexpr double no_angle = std::numeric_limits<double>::quiet_NaN();  // compares as far from all
  Angles recent_ = Angles::Constant(no_angle), recent_cos_ = Angles::Zero(), recent_sin_ = Angles::Zero();
};

}  // namespace numlab::mechanisms
