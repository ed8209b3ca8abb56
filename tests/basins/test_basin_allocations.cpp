// A basin start allocates nothing on the heap: Newton on the fixed-size Jansen closure, the slice's
// starting point and the mode check against the branch's closed form. Built like test_allocations
// (Eigen's runtime no-malloc check force-included, the sources compiled here): each refused Eigen
// allocation is counted.

#include <catch2/catch.hpp>

#include "basins/basin_systems.hpp"
#include "numlab/mechanisms/jansen_closure.hpp"
#include "numlab/nonlinear/basin_map.hpp"

using namespace numlab;

TEST_CASE("The counter sees an Eigen allocation (so the zero below means something)", "[basins][allocations]") {
  refused_eigen_allocations = 0;
  Eigen::internal::set_is_malloc_allowed(false);
  Eigen::VectorXd dynamic(64);
  dynamic.setZero();
  Eigen::internal::set_is_malloc_allowed(true);
  CHECK(refused_eigen_allocations >= 1);
}

TEST_CASE("A Jansen basin start, with its mode check, allocates nothing", "[basins][allocations]") {
  using Closure = mechanisms::JansenClosureOf<mechanisms::TableSines>;
  const double crank = mechanisms::JansenClosure::seed_crank_angle;
  const Closure closure(crank);
  const basins::JansenModes modes(crank);
  linalg::Vector<8> base = mechanisms::JansenClosure::seed_estimates();
  nonlinear::BasinSlice slice;
  slice.axis_u = 0;
  slice.axis_v = 6;
  slice.u_min = base(0) - 3;
  slice.u_max = base(0) + 3;
  slice.v_min = base(6) - 3;
  slice.v_max = base(6) + 3;
  slice.columns = slice.rows = 9;
  nonlinear::Newton<Closure> newton(closure, {});
  const auto classify = [&modes](const linalg::Vector<8>& theta) { return modes.mode_of(theta); };
  (void)nonlinear::basin_point(newton, base, slice, 4, 4, classify);  // the sine table is filled before counting
  int converged = 0, failed = 0;
  refused_eigen_allocations = 0;
  Eigen::internal::set_is_malloc_allowed(false);
  for (int j = 0; j < slice.rows; ++j) {
    for (int i = 0; i < slice.columns; ++i) {
      const auto point = nonlinear::basin_point(newton, base, slice, i, j, classify);
      (point.status == Status::converged ? converged : failed) += 1;
    }
  }
  Eigen::internal::set_is_malloc_allowed(true);
  CHECK(converged > 0);
  CHECK(failed > 0);  // both paths taken
  CHECK(refused_eigen_allocations == 0);
}
