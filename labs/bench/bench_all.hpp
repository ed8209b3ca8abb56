#pragma once
// `numlab bench` with no argument: everything, measured and charted.
//   - the work-precision diagram: every Jansen solver over Newton tolerances 1e-2 .. 1e-13, median
//     time per cycle against the worst joint error vs the closed form (the closed form a point);
//   - linear solvers: time against n;  Gauss-Seidel: sweeps against kappa;
//   - fitting: digits against degree.
// Each chart gets its CSV and gnuplot script beside it.

#include <string>

#include "bench/bench_options.hpp"
#include "output/exit_codes.hpp"
#include "output/files.hpp"

namespace numlab::cli {

// `chart` names the work-precision chart (default OUT/work-precision.svg); the others go to OUT/.
int run_bench_all(const BenchOptions& common, const std::string& chart, bool quick);

}  // namespace numlab::cli
