#pragma once
// `numlab bench jansen`: the time per 360-pose crank cycle of every Jansen solver at one Newton
// tolerance, its worst joint error against the closed form, and the ratios the toolkit aims for.
// Timed is mechanisms::solve_crank_sweep() alone, the same work for every solver: the solve from
// the seed's estimates, then per pose the prediction, the pose solve and storing its angles.
// The joints and the checks against the closed form are computed afterwards, untimed.

#include <string>
#include <vector>

#include "numlab/mechanisms/jansen_solvers.hpp"

namespace numlab::cli {

struct JansenBenchRow {
  std::string solver;  // full, full-std-sin, full-gauss-seidel, full-gsl-lu, full-eigen-lu, sequential, analytic,
                       // gsl-<type>; file-full, file-sequential, file-analytic (bench_jansen_file)
  mechanisms::JansenModel model;
  double tolerance;
  double time_s;  // median per cycle
  double error;   // worst joint distance from the closed form over the cycle
  int iterations; // summed over the cycle
};

// One row per solver (all eight GSL types included unless `quick`). Every closure takes its sines
// from the table (sine_sources.hpp) but the row full-std-sin's: full Newton on the textbook
// closure, std::sin and std::cos, so that the table's gain is measured.
std::vector<JansenBenchRow> bench_jansen(mechanisms::JansenModel model, double tolerance, bool quick);

// Rows file-full, file-sequential, file-analytic: the same leg from mechanisms/models/jansen.toml,
// its derived model (12 joint coordinates) solved by the generic linkage solvers over the same cycle
// (linkage_sweep.hpp's solve_linkage_cycle), error against the hand-coded closed form.
std::vector<JansenBenchRow> bench_jansen_file(double tolerance, bool quick);

// How a solver is named in printed tables: "full, std::sin" for full-std-sin, else its name.
std::string jansen_bench_label(const std::string& solver);

// Prints the table and the three target ratios; returns the JSON rows.
void print_jansen_bench(std::ostream& out, const std::vector<JansenBenchRow>& rows);

}  // namespace numlab::cli
