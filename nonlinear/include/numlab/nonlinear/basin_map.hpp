#pragma once
// A basin map: Newton from every point of a planar slice of starting guesses, and where each start
// ends up.
//
// The slice: two chosen unknowns (axis u, axis v) run over a grid of columns x rows points; every
// other unknown stays at `base`. Point (i, j) starts at
//   x0 = base,  x0(u) = u_min + (u_max - u_min) i / (columns - 1),  x0(v) = v_min + (v_max - v_min) j / (rows - 1)
// (a one-point axis sits at its minimum). Newton (newton.hpp, plain or damped) runs from x0; the point
// records its status, its iterations and, when it converged, the mode its root belongs to, as told by
// `classify` (which returns a mode number >= 0, or unknown_mode for a root that matches no known mode).
//
// In parallel: `threads` workers take rows one at a time from a shared counter; each has its own
// Newton and its own vectors, the system is only read (const), and each point's result goes to its
// own slot. A point's result depends on its coordinates alone, so the map is the same for any
// number of threads.

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "numlab/nonlinear/newton.hpp"

namespace numlab::nonlinear {

struct BasinSlice {
  int axis_u = 0, axis_v = 1;  // which unknowns run along the columns (u) and the rows (v)
  double u_min = -1.0, u_max = 1.0, v_min = -1.0, v_max = 1.0;
  int columns = 2, rows = 2;

  double u(int i) const { return columns == 1 ? u_min : u_min + (u_max - u_min) * i / (columns - 1); }
  double v(int j) const { return rows == 1 ? v_min : v_min + (v_max - v_min) * j / (rows - 1); }
};

// Mode numbers beside the known modes (0, 1, ...).
inline constexpr int unknown_mode = -1;  // converged to a root that matches no known mode
inline constexpr int no_mode = -2;       // did not converge

struct BasinPoint {
  Status status = Status::running;
  std::int16_t mode = no_mode;
  std::int16_t iterations = 0;
};

struct BasinMap {
  BasinSlice slice;
  std::vector<BasinPoint> points;  // row j, column i at j * columns + i
  const BasinPoint& at(int i, int j) const { return points[static_cast<std::size_t>(j) * slice.columns + i]; }
};

// Throws std::invalid_argument for an empty grid, an axis out of range or twice, or a range that is
// not finite and increasing.
inline void check_slice(const BasinSlice& slice, int unknowns) {
  if (slice.columns < 1 || slice.rows < 1) throw std::invalid_argument("a basin grid needs at least 1 x 1 points");
  if (slice.axis_u < 0 || slice.axis_u >= unknowns || slice.axis_v < 0 || slice.axis_v >= unknowns ||
      slice.axis_u == slice.axis_v) {
    throw std::invalid_argument("a basin slice needs two different unknowns of the " + std::to_string(unknowns));
  }
  // The width too: u_max - u_min must not overflow (-1e308:1e308), or every start would be inf.
  const auto increasing = [](double low, double high) { return std::isfinite(high - low) && low < high; };
  if (!increasing(slice.u_min, slice.u_max) || !increasing(slice.v_min, slice.v_max)) {
    throw std::invalid_argument("a basin slice's ranges must be finite with min < max and a finite width");
  }
}

// Newton from one grid point: the point's record. `newton` is the caller's own (reused, no heap).
template <typename NewtonType, typename Classify>
BasinPoint basin_point(NewtonType& newton, const Vector<NewtonType::N>& base, const BasinSlice& slice, int i, int j,
                       const Classify& classify) {
  Vector<NewtonType::N> x0 = base;
  x0(slice.axis_u) = slice.u(i);
  x0(slice.axis_v) = slice.v(j);
  newton.start(x0);
  while (newton.step()) {
  }
  BasinPoint point;
  point.status = newton.status();
  point.iterations = static_cast<std::int16_t>(newton.iterations());
  if (point.status == Status::converged) point.mode = static_cast<std::int16_t>(classify(newton.x()));
  return point;
}

// The map of `system` over `slice` with `threads` workers (at least 1).
template <NonlinearSystem S, typename Classify>
BasinMap basin_map(const S& system, const Vector<S::size>& base, const BasinSlice& slice, const NewtonOptions& options,
                   const Classify& classify, int threads) {
  check_slice(slice, system.dimension());
  linalg::require_finite(base, "basin slice's base point");
  if (threads < 1) throw std::invalid_argument("a basin map needs at least 1 thread");
  if (options.max_iterations > 32767) throw std::invalid_argument("a basin map counts at most 32767 iterations");
  Newton<S> checked(system, options);  // bad options throw here, not inside a worker thread
  BasinMap map{slice, std::vector<BasinPoint>(static_cast<std::size_t>(slice.columns) * slice.rows)};
  std::atomic<int> next_row{0};
  // An exception never leaves a worker (it would end the program): the first one is kept, the
  // other workers stop taking rows, and it is rethrown here once every worker has been joined.
  std::exception_ptr failure;
  std::mutex failure_lock;
  const auto work = [&] {
    try {
      Newton<S> newton(system, options);  // this worker's own Newton and vectors
      for (int j = next_row++; j < slice.rows; j = next_row++) {
        for (int i = 0; i < slice.columns; ++i) {
          map.points[static_cast<std::size_t>(j) * slice.columns + i] = basin_point(newton, base, slice, i, j, classify);
        }
      }
    } catch (...) {
      next_row = slice.rows;
      const std::lock_guard<std::mutex> hold(failure_lock);
      if (!failure) failure = std::current_exception();
    }
  };
  std::vector<std::thread> workers;
  try {
    for (int t = 1; t < std::min(threads, slice.rows); ++t) workers.emplace_back(work);
  } catch (...) {  // a thread that cannot start: stop and join the ones that did
    next_row = slice.rows;
    for (std::thread& worker : workers) worker.join();
    throw;
  }
  work();  // this thread is a worker too
  for (std::thread& worker : workers) worker.join();
  if (failure) std::rethrow_exception(failure);
  return map;
}

}  // namespace numlab::nonlinear
