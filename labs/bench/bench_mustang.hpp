#pragma once
// `numlab bench mustang`: the time per sweep over the Mustang linkage's assembly range for every
// solver, as ratios to full Newton, with each solver's worst joint error against the closed form.

#include <ostream>
#include <string>
#include <vector>

#include "bench/bench_options.hpp"
#include "output/exit_codes.hpp"
#include "output/files.hpp"

namespace numlab::cli {

struct MustangBenchRow {
  std::string solver;  // full, full-gsl-lu, full-eigen-lu, full-gauss-seidel, sequential, analytic, gsl-<type>
  double tolerance;
  double time_s;       // median per sweep
  int poses;
  double error;        // worst joint distance from the closed form over the sweep
  int iterations;      // summed over the sweep
};

// The sweep timed: -41:56:0.5 deg (195 poses, all inside the range), from the seed's start.
std::vector<MustangBenchRow> bench_mustang(double tolerance, bool quick);
void print_mustang_bench(std::ostream& out, const std::vector<MustangBenchRow>& rows);

// `numlab bench mustang [--format json] [--tol T] [--quick]`.
int run_mustang_bench(const BenchOptions& common, bool quick);

}  // namespace numlab::cli
