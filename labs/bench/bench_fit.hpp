#pragma once
// `numlab bench fit` (and the fitting part of `numlab bench`): every fit method at degrees
// 1 .. 12 on NIST Wampler4, its correct digits against the extended-precision reference, and the
// median time per fit; a chart of digits and residual against degree.

#include <iosfwd>
#include <string>
#include <vector>

#include "bench/bench_options.hpp"
#include "output/exit_codes.hpp"
#include "output/files.hpp"
#include "numlab/fitting/degree_sweep.hpp"
#include "numlab/fitting/data_set.hpp"

namespace numlab::cli {

struct FitBenchRow {
  fitting::DegreeSweepRow sweep;
  std::string data;
  double time_s;  // median per fit
};

// The degree sweep of fit_degree_sweep(), each fit timed.
std::vector<FitBenchRow> bench_fit(const std::string& data_name, const fitting::DataSet& data, int max_degree,
                                   bool quick);

// Correct digits per degree (rows) and method (columns), or the status where a fit gave no coefficients.
void print_fit_digits(std::ostream& out, const std::vector<FitBenchRow>& rows);

// `numlab bench fit`: NIST Wampler4 (found by nist_data_dir()), the table, and OUT/bench-fit.svg
// (or `chart`) with its CSV and script.
int run_bench_fit(const BenchOptions& common, const std::string& chart, bool quick);

}  // namespace numlab::cli
