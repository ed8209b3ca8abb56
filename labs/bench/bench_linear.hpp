#pragma once
// `numlab bench linear` (and `numlab bench jansen`, see bench_jansen.hpp): median time per solve for GEPP, GSL LU, Eigen LU and Gauss-Seidel
// against n, with ratios to GSL LU and a log-log chart with an n^3 guide.

#include <string>
#include <vector>

#include "output/chart.hpp"
#include "bench/bench_options.hpp"
#include "output/table.hpp"

namespace numlab::cli {

struct BenchRow {
  std::string solver;
  int n;
  double time_s;  // median per solve
  double error;   // forward error against the exact solution (all ones)
};

// Times every linear solver at each size (fixed-size code at n = 2 and 8).
std::vector<BenchRow> bench_linear(const std::vector<int>& sizes, bool quick);

// Median time per solve, and the ratio to GSL LU, per size (rows) and solver (columns).
Table linear_bench_table(const std::vector<BenchRow>& rows, const std::vector<int>& sizes);

// Time per solve against n, log-log, with an n^3 guide; CSV and gnuplot script beside it.
void draw_linear_chart(const ChartFiles& files, const std::vector<BenchRow>& rows, const std::vector<int>& sizes);

// numlab bench linear: the table (or JSON, CSV) and the chart. Returns the exit code.
int run_linear_bench(const BenchOptions& options, const std::string& chart, const std::vector<int>& sizes, bool quick);
// numlab bench jansen: the seeds' models and the description file, every solver.
int run_jansen_bench(const BenchOptions& options, bool quick);

}  // namespace numlab::cli
