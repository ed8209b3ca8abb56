#pragma once
// Cosines and sines from a table, for angles that Newton's iterates and a crank sweep's poses
// move only a little: the fast path beside std::cos and std::sin.
//
// An angle t is anchored at the nearest node a = k/64 of a table of std::cos and std::sin
// (|t| <= 32 rad; farther out, and for non-finite t, the library is called). With d = t - a
// (exact, |d| <= 1/128) the angle-addition formulas give
//   cos t = cos a + (cos a (cos d - 1) - sin a sin d),
//   sin t = sin a + (sin a (cos d - 1) + cos a sin d),
// with sin d and cos d - 1 from their Taylor series (the first omitted terms, d^7/7! and d^8/8!,
// are below 4e-19: a five-hundredth of an ulp of 1). Results agree with std::cos and std::sin to
// a few units in the last place.
//
// table_sincos() is that and nothing else: a pure function of t (the table is filled once, on
// first use, and never changes), safe to call from any thread. AnchoredSinCos<N> adds a cache
// for one caller: the angle last reached through the table is kept ("recent"), and a Newton
// correction away from it (|h| <= 2^-20) needs only sin h = h and cos h - 1 = -h^2/2 (the next
// terms are below 2e-19). Every value is at most two such steps from a library value, so nothing
// drifts.

#include <Eigen/Core>
#include <array>
#include <cmath>
#include <limits>

#include "numlab/force_inline.hpp"
#include "numlab/linalg/linear_result.hpp"

namespace numlab::mechanisms {

// std::cos and std::sin at the nodes k/64, |k| <= reach.
struct SinCosNodes {
  static constexpr double per_radian = 64.0;
  static constexpr int reach = 2048;
  static constexpr double limit = (reach - 1) / per_radian;  // |t| beyond: the library
  std::array<double, 2 * reach + 1> cos, sin;               // index k + reach
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

namespace detail {

// (cos, sin) of a + d from cos a and sin a, |d| <= 1/128: sin d and cos d - 1 by Horner's rule on
// their Taylor series, then the angle-addition formulas with the small correction added last.
// T is double, or Eigen::Array2d for two angles at once.
template <typename T>
NUMLAB_FORCE_INLINE void rotate_by(const T& d, const T& cos_a, const T& sin_a, T& c, T& s) {
  const T d2 = d * d;
  const T sin_d = d + d * d2 * (-1.0 / 6 + d2 * (1.0 / 120));
  const T cos_d_minus_1 = d2 * (-1.0 / 2 + d2 * (1.0 / 24 + d2 * (-1.0 / 720)));
  c = cos_a + (cos_a * cos_d_minus_1 - sin_a * sin_d);
  s = sin_a + (sin_a * cos_d_minus_1 + cos_a * sin_d);
}

// The same for a Newton correction h, |h| <= 2^-20: sin h = h and cos h - 1 = -h^2/2.
template <typename T>
NUMLAB_FORCE_INLINE void correct_by(const T& h, const T& cos_a, const T& sin_a, T& c, T& s) {
  const T cos_h_minus_1 = -0.5 * h * h;
  c = cos_a + (cos_a * cos_h_minus_1 - sin_a * h);
  s = sin_a + (sin_a * cos_h_minus_1 + cos_a * h);
}

// The nearest node k/64 to t (adding and subtracting 1.5 * 2^52 rounds to an integer).
template <typename T>
NUMLAB_FORCE_INLINE T nearest_node(const T& t) {
  constexpr double rounder = 0x1.8p52;
  return (t * SinCosNodes::per_radian + rounder) - rounder;
}

inline int table_index(double node) { return static_cast<int>(node) + SinCosNodes::reach; }

// One angle within the table (|t| <= SinCosNodes::limit), from its nearest node.
NUMLAB_FORCE_INLINE void from_node(double t, double& c, double& s) {
  const SinCosNodes& nodes = sincos_nodes();
  const double node = nearest_node(t);
  const int i = table_index(node);
  rotate_by(t - node / SinCosNodes::per_radian, nodes.cos[i], nodes.sin[i], c, s);
}

// Two angles within the table, in the lanes of one Eigen::Array2d (one SSE2 register).
NUMLAB_FORCE_INLINE void from_nodes(const Eigen::Array2d& t, Eigen::Array2d& c, Eigen::Array2d& s) {
  using Pair = Eigen::Array2d;
  const SinCosNodes& nodes = sincos_nodes();
  const Pair node = nearest_node(t);
  const int i = table_index(node(0)), j = table_index(node(1));
  rotate_by<Pair>(t - node / SinCosNodes::per_radian, Pair(nodes.cos[i], nodes.cos[j]), Pair(nodes.sin[i], nodes.sin[j]),
                  c, s);
}

inline bool within_table(double t) { return std::abs(t) <= SinCosNodes::limit; }  // false for NaN

}  // namespace detail

// c = cos t and s = sin t: from the table's nearest node, or beyond the table from the library.
NUMLAB_FORCE_INLINE void table_sincos(double t, double& c, double& s) {
  if (detail::within_table(t)) {
    detail::from_node(t, c, s);
  } else {
    c = std::cos(t);  // one argument for both: the compiler makes one sincos call
    s = std::sin(t);
  }
}

// Two angles at once: both through the table when both lie within it, else one at a time.
NUMLAB_FORCE_INLINE void table_sincos(const Eigen::Array2d& t, Eigen::Array2d& c, Eigen::Array2d& s) {
  if (detail::within_table(t(0)) && detail::within_table(t(1))) {
    detail::from_nodes(t, c, s);
  } else {
    table_sincos(t(0), c(0), s(0));
    table_sincos(t(1), c(1), s(1));
  }
}

// The table plus a per-angle cache of the recent angle, for one non-const caller (DyadNewton).
template <int N>
class AnchoredSinCos {
 public:
  static constexpr double largest_correction = 0x1p-20;
  static constexpr double table_limit = SinCosNodes::limit;

  // c_k = cos theta_k and s_k = sin theta_k for every k, two angles at a time.
  NUMLAB_FORCE_INLINE void evaluate(const linalg::Vector<N>& theta, linalg::Vector<N>& c, linalg::Vector<N>& s) {
    if constexpr (N >= 2) {
      for (int k = 0; k + 1 < N; k += 2) evaluate_pair(k, theta, c, s);
    }
    if constexpr (N % 2 == 1) evaluate_one(N - 1, theta(N - 1), c(N - 1), s(N - 1));
  }

 private:
  using Pair = Eigen::Array2d;
  using Angles = Eigen::Array<double, N, 1>;

  // Angles k and k + 1 by one path for both: corrections when both moved by a Newton correction,
  // else the table when both lie within it, else one at a time.
  NUMLAB_FORCE_INLINE void evaluate_pair(int k, const linalg::Vector<N>& theta, linalg::Vector<N>& c,
                                         linalg::Vector<N>& s) {
    const Pair t = theta.template segment<2>(k).array();
    const Pair h = t - recent_.template segment<2>(k);
    Pair cos_t, sin_t;
    if (std::abs(h(0)) <= largest_correction && std::abs(h(1)) <= largest_correction) {
      detail::correct_by<Pair>(h, recent_cos_.template segment<2>(k), recent_sin_.template segment<2>(k), cos_t, sin_t);
      c.template segment<2>(k).array() = cos_t;
      s.template segment<2>(k).array() = sin_t;
      return;
    }
    if (detail::within_table(t(0)) && detail::within_table(t(1))) {
      detail::from_nodes(t, cos_t, sin_t);
      c.template segment<2>(k).array() = cos_t;
      s.template segment<2>(k).array() = sin_t;
      recent_.template segment<2>(k) = t;
      recent_cos_.template segment<2>(k) = cos_t;
      recent_sin_.template segment<2>(k) = sin_t;
      return;
    }
    evaluate_one(k, t(0), c(k), s(k));
    evaluate_one(k + 1, t(1), c(k + 1), s(k + 1));
  }

  // One angle: 1. a Newton correction from the recent angle, 2. else the table (or the library).
  void evaluate_one(int k, double t, double& c, double& s) {
    const double h = t - recent_(k);
    if (std::abs(h) <= largest_correction) {
      detail::correct_by(h, recent_cos_(k), recent_sin_(k), c, s);
      return;
    }
    table_sincos(t, c, s);
    recent_(k) = t;
    recent_cos_(k) = c;
    recent_sin_(k) = s;
  }

  static constexpr double no_angle = std::numeric_limits<double>::quiet_NaN();  // compares as far from all
  Angles recent_ = Angles::Constant(no_angle), recent_cos_ = Angles::Zero(), recent_sin_ = Angles::Zero();
};

}  // namespace numlab::mechanisms
