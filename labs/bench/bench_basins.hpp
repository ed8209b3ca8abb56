#pragma once
// `numlab bench basins`: how fast a basin map runs. Solves per second of the Jansen leg's map
// (plain Newton, 20 iterations at most, tolerance 1e-9) on 1 thread and on 2, their ratio, the cost
// of one basin solve against one pose of the crank sweep (the same Newton and tolerance), and the
// time of a 1000 x 1000 map on every core. Medians of repeated in-process runs; the runs being
// compared alternate, so that a ratio comes from one run of the program.

#include "bench/bench_options.hpp"
#include "output/exit_codes.hpp"
#include "output/files.hpp"

namespace numlab::cli {

// `numlab bench basins [--format json] [--quick]`.
int run_basins_bench(const BenchOptions& common, bool quick);

}  // namespace numlab::cli
