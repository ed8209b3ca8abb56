#pragma once
// Where a Jansen closure takes its sines and cosines from: the template argument of
// JansenClosureOf and Jansen10ClosureOf.
//
//   LibrarySines  std::cos and std::sin: the textbook closure, the one students read and trace;
//   TableSines    the k/64 node table plus a short series (anchored_sincos.hpp): the fast path
//                 the crank sweep and the benchmark use, agreeing with the library to a few ulp.
//
// Both are pure: static functions with no state, so a const closure may be evaluated from
// several threads at once.

#include <Eigen/Core>
#include <cmath>

#include "numlab/force_inline.hpp"
#include "numlab/linalg/linear_result.hpp"
#include "numlab/mechanisms/anchored_sincos.hpp"

namespace numlab::mechanisms {

struct LibrarySines {
  static void one(double t, double& c, double& s) {
    c = std::cos(t);
    s = std::sin(t);
  }
  // c_k = cos theta_k, s_k = sin theta_k.
  template <int N>
  static void evaluate(const linalg::Vector<N>& theta, linalg::Vector<N>& c, linalg::Vector<N>& s) {
    for (int k = 0; k < N; ++k) one(theta(k), c(k), s(k));
  }
};

struct TableSines {
  static void one(double t, double& c, double& s) { table_sincos(t, c, s); }
  // The same, two angles at a time (one SSE2 register holds both).
  template <int N>
  NUMLAB_FORCE_INLINE static void evaluate(const linalg::Vector<N>& theta, linalg::Vector<N>& c, linalg::Vector<N>& s) {
    for (int k = 0; k + 1 < N; k += 2) {
      Eigen::Array2d cos_t, sin_t;
      table_sincos(Eigen::Array2d(theta.template segment<2>(k).array()), cos_t, sin_t);
      c.template segment<2>(k).array() = cos_t;
      s.template segment<2>(k).array() = sin_t;
    }
    if constexpr (N % 2 == 1) table_sincos(theta(N - 1), c(N - 1), s(N - 1));
  }
};

}  // namespace numlab::mechanisms
