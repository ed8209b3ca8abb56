#pragma once
// `numlab bench quick-return`: the Whitworth quick-return read from mechanisms/models/whitworth.toml
// (joint coordinates, a slider on a moving link and one on the ground, derived by the linkage
// solver) against a hand-written solver of the same mechanism, over one 360-pose crank cycle. Issue
// 30 asks the file to stay within 2x of the hand-written solver. Timed is the pose solving alone,
// as `bench jansen` times its file rows (solve_linkage_cycle: the prediction, the pose solve, the
// unknowns stored); the error against the closed form is computed afterwards, untimed.

#include <string>
#include <vector>

#include "bench/bench_options.hpp"

namespace numlab::cli {

struct QuickReturnBenchRow {
  std::string solver;  // whitworth.toml, full | sequential; hand-written Newton; closed form
  double time_s;       // median per cycle
  double error;        // worst joint distance from the closed form over the cycle (inf: a pose failed)
  int iterations;      // summed over the cycle
};

std::vector<QuickReturnBenchRow> bench_quick_return(double tolerance, bool quick);

// `numlab bench quick-return [--format json] [--tol T] [--quick]`.
int run_quick_return_bench(const BenchOptions& common, bool quick);

}  // namespace numlab::cli
