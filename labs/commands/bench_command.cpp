#include "commands/bench_command.hpp"

#include <CLI/CLI.hpp>

#include <stdexcept>

#include "bench/bench_all.hpp"
#include "bench/bench_basins.hpp"
#include "bench/bench_fit.hpp"
#include "bench/bench_grade.hpp"
#include "bench/bench_linear.hpp"
#include "bench/bench_linkage_scaling.hpp"
#include "bench/bench_mustang.hpp"
#include "bench/bench_quick_return.hpp"
#include "bench/bench_robustness.hpp"

namespace numlab::cli {

BenchCommand::BenchCommand(CLI::App& app) {
  command_ = app.add_subcommand("bench", "Measure speed: median of repeated in-process runs, as ratios");
  command_->add_option("what", what_,
                       "What to measure: all (default), linear, jansen, mustang, quick-return, fit, basins, robustness, "
                       "linkage-scaling or grade (numlab exercise grade on 300 Python GEPP submissions)")
      ->check(CLI::IsMember({"all", "linear", "jansen", "mustang", "quick-return", "fit", "basins", "robustness",
                             "linkage-scaling", "grade"}));
  command_->add_option("--chart", chart_,
                       "Main chart (.svg or .png); default OUT/work-precision.svg (all) or OUT/bench-linear.svg");
  command_->add_option("--sizes", sizes_, "Sizes n, comma-separated")->delimiter(',')->check(CLI::Range(1, 4096));
  command_->add_flag("--quick", quick_, "Fewer repetitions (a smoke run, not a measurement)");
  add_common_options(*command_, common_);
}

int BenchCommand::run() const {
  // Every flag checked against what is measured, and every file named, before any measuring.
  const CommonOptions common = checked_common_options(common_, "bench " + what_);
  require_applies(given(*command_, "--chart"), what_ == "all" || what_ == "linear" || what_ == "fit", "--chart",
                  "bench all, bench linear and bench fit");
  require_applies(given(*command_, "--sizes"), what_ == "linear", "--sizes", "bench linear");
  // Newton stops on ||f||_inf <= --tol: at 0 rounding never lets it stop, so there is nothing to time.
  if (common.tolerance && *common.tolerance == 0.0) {
    throw std::invalid_argument("--tol 0: bench " + what_ +
                                " times Newton to a residual tolerance, which must be above 0 (e.g. --tol 1e-10)");
  }
  const std::string chart = output_path(common, chart_);
  const BenchOptions bench_options{common.format, common.out_dir, common.tolerance};
  if (what_ == "all") return run_bench_all(bench_options, chart, quick_);
  if (what_ == "jansen") return run_jansen_bench(bench_options, quick_);
  if (what_ == "mustang") return run_mustang_bench(bench_options, quick_);
  if (what_ == "quick-return") return run_quick_return_bench(bench_options, quick_);
  if (what_ == "fit") return run_bench_fit(bench_options, chart, quick_);
  if (what_ == "basins") return run_basins_bench(bench_options, quick_);
  if (what_ == "robustness") return run_bench_robustness(bench_options, quick_);
  if (what_ == "linkage-scaling") return run_linkage_scaling_bench(bench_options, quick_);
  if (what_ == "grade") return run_grade_bench(bench_options, quick_);
  return run_linear_bench(bench_options, chart, sizes_, quick_);
}

}  // namespace numlab::cli
