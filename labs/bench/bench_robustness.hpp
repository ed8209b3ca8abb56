#pragma once
// `numlab bench robustness`: every MINPACK test case (problem x size x start) run by every solver
// (bench/robustness_runs.hpp), and what the runs show:
//   - the success table: problem x start x solver, "solved" or the status and the final ||f||_inf
//     (OUT/robustness-success.csv, .txt and .md);
//   - Dolan-Moré performance profiles on time and on function evaluations, and the Moré-Wild data
//     profile (OUT/robustness-profile-time.svg, robustness-profile-evaluations.svg,
//     robustness-data-profile.svg, each with its CSV and gnuplot script beside it).

#include <string>
#include <vector>

#include "bench/robustness_runs.hpp"
#include "bench/bench_options.hpp"
#include "output/exit_codes.hpp"
#include "output/files.hpp"
#include "output/profile_charts.hpp"
#include "output/table.hpp"

namespace numlab::cli {

// One line for every chart and table: what "solved" means and the budget.
std::string solved_definition();

// Solvers that run on every case (the ones the profiles compare), in table order.
std::vector<std::string> profiled_solvers(const RobustnessResults& results);

// Cases solved by `solver`, and the cases it applies to.
int solved_count(const RobustnessResults& results, const std::string& solver);
int applicable_count(const RobustnessResults& results, const std::string& solver);

// Per solver: solved, of the cases it applies to, and the median evaluations where solved.
Table success_counts_table(const RobustnessResults& results);
// One row per case, one column per solver: outcome_text() of each run.
Table success_table(const RobustnessResults& results);

// The three profiles over the profiled solvers.
ProfileCurves time_profile(const RobustnessResults& results);
ProfileCurves evaluation_profile(const RobustnessResults& results);
ProfileCurves data_profile_curves(const RobustnessResults& results);

// The files a run writes into `folder`, in the order written: three tables, three charts.
struct RobustnessFiles {
  std::string csv, text, markdown;
  ChartFiles time_chart, evaluation_chart, data_chart;
};
RobustnessFiles robustness_files(const std::string& folder);
std::vector<PlannedFile> planned_files(const RobustnessFiles& files);
// Writes the tables (each whole or not at all) and draws the charts.
void write_robustness_files(const RobustnessFiles& files, const RobustnessResults& results);

int run_bench_robustness(const BenchOptions& common, bool quick);

}  // namespace numlab::cli
