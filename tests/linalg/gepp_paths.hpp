#pragma once
// GEPP has two paths to one answer: the textbook stepper (start, step() until done, result()) and
// the fast path of solve() and solve_prechecked() (gauss_elimination_kernel.hpp). They must agree
// bit for bit: the same x, status, pivot columns, growth factor and residual.

#include <bit>
#include <catch2/catch.hpp>
#include <cstdint>
#include <sstream>

#include "numlab/linalg/gauss_elimination.hpp"

namespace numlab::test {

inline bool same_bits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

template <int N>
bool same_bits(const linalg::Vector<N>& a, const linalg::Vector<N>& b) {
  if (a.size() != b.size()) return false;
  for (Eigen::Index i = 0; i < a.size(); ++i) {
    if (!same_bits(a(i), b(i))) return false;
  }
  return true;
}

template <int N>
std::string all_digits(const linalg::Vector<N>& v) {
  std::ostringstream text;
  text.precision(17);
  text << v.transpose();
  return text.str();
}

// The stepped result, after checking that the fast paths give the same.
template <int N>
linalg::LinearResult<N> check_gepp_paths_agree(const linalg::Matrix<N>& A, const linalg::Vector<N>& b,
                                               linalg::GaussEliminationOptions options = {}) {
  linalg::GaussElimination<N> stepper(options);
  stepper.start(A, b);
  while (stepper.step()) {
  }
  const linalg::LinearResult<N> stepped = stepper.result();
  const linalg::LinearResult<N> fast = linalg::GaussElimination<N>(options).solve(A, b);
  const linalg::LinearResult<N> prechecked = linalg::GaussElimination<N>(options).solve_prechecked(A, b);

  INFO("stepped x = " << all_digits(stepped.x));
  INFO("solve() x = " << all_digits(fast.x));
  INFO("solve_prechecked() x = " << all_digits(prechecked.x));
  CHECK(stepped.status == fast.status);
  CHECK(stepped.iterations == fast.iterations);
  CHECK(same_bits(stepped.x, fast.x));
  CHECK(same_bits(stepped.growth_factor, fast.growth_factor));
  CHECK(same_bits(stepped.residual_norm, fast.residual_norm));
  CHECK(prechecked.status == fast.status);
  CHECK(prechecked.iterations == fast.iterations);
  CHECK(same_bits(prechecked.x, fast.x));
  return stepped;
}

}  // namespace numlab::test
