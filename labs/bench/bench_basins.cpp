#include "bench/bench_basins.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <iostream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <thread>
#include <vector>

#include "basins/basin_run.hpp"
#include "bench/timing.hpp"
#include "numlab/mechanisms/jansen_solvers.hpp"
#include "output/table.hpp"

namespace numlab::cli {

namespace {

double median(std::vector<double> values) {
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}

basins::BasinRequest jansen_map(int side, int threads) {
  basins::BasinRequest request;
  request.system = "jansen";
  request.columns = request.rows = side;
  request.threads = threads;
  return request;
}

long long iterations_of(const nonlinear::BasinMap& map) {
  long long total = 0;
  for (const auto& point : map.points) total += point.iterations;
  return total;
}

}  // namespace

int run_basins_bench(const CommonOptions& common, bool quick) {
  const int cores = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  const int side = quick ? 100 : 300, repeats = quick ? 3 : 7;
  // 1. Threads 1 and 2, alternating, on the same map.
  //    Beside the wall times, the CPU time of the whole process over each run (all threads): on a
  //    machine shared with other work the wall-clock speed-up shows the sharing, the CPU times show
  //    whether the threads themselves add work.
  std::vector<double> one, two, cpu_one, cpu_two;
  nonlinear::BasinMap map;
  const auto cpu_seconds = [] { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; };
  for (int run = 0; run < repeats; ++run) {
    double cpu = cpu_seconds();
    const auto single = basins::run_basins(jansen_map(side, 1));
    cpu_one.push_back(cpu_seconds() - cpu);
    one.push_back(single.seconds);
    cpu = cpu_seconds();
    two.push_back(basins::run_basins(jansen_map(side, 2)).seconds);
    cpu_two.push_back(cpu_seconds() - cpu);
    map = single.map;
  }
  const double solves = static_cast<double>(side) * side;
  const double t1 = median(one), t2 = median(two);
  const double basin_iterations = static_cast<double>(iterations_of(map)) / solves;

  // 2. One pose of the crank sweep: full Newton (GEPP) on the same closure, same tolerance and limit.
  nonlinear::NewtonOptions options;
  options.max_iterations = 20;
  const auto solver = mechanisms::make_jansen_solver(mechanisms::JansenModel::eight_equations, "full", "gepp", options);
  const double start = mechanisms::JansenClosure::seed_crank_angle * 180.0 / std::numbers::pi;
  const auto cycle = [&] {
    return mechanisms::solve_crank_sweep(mechanisms::JansenModel::eight_equations, *solver, start, start + 359.0, 1.0);
  };
  int sweep_iterations = 0;
  for (const auto& outcome : cycle().outcomes) sweep_iterations += outcome.iterations;
  const double pose_s = median_time(cycle, quick ? TimingPlan{3, 10, 0.0} : TimingPlan{7, 1000, 0.3}) / 360.0;
  const double solve_s = t1 / solves;

  // 3. The 1000 x 1000 map on every core (a 400 x 400 one with --quick).
  const int big = quick ? 400 : 1000;
  std::vector<double> big_times, big_cpu;
  for (int run = 0; run < (quick ? 1 : 3); ++run) {
    const double cpu = cpu_seconds();
    big_times.push_back(basins::run_basins(jansen_map(big, cores)).seconds);
    big_cpu.push_back(cpu_seconds() - cpu);
  }
  const double big_s = median(big_times), big_cpu_s = median(big_cpu);

  if (common.format == Format::json) {
    nlohmann::ordered_json out = {{"benchmark", "basins"},
                                  {"grid", side},
                                  {"runs", repeats},
                                  {"time_1_thread_s", t1},
                                  {"time_2_threads_s", t2},
                                  {"solves_per_second_1_thread", solves / t1},
                                  {"solves_per_second_2_threads", solves / t2},
                                  {"speed_up_2_threads", t1 / t2},
                                  {"iterations_per_solve", basin_iterations},
                                  {"time_per_solve_s", solve_s},
                                  {"time_per_sweep_pose_s", pose_s},
                                  {"iterations_per_sweep_pose", sweep_iterations / 360.0},
                                  {"solve_to_pose_ratio", solve_s / pose_s},
                                  {"big_grid", big},
                                  {"big_threads", cores},
                                  {"big_time_s", big_s},
                                  {"cpu_1_thread_s", median(cpu_one)},
                                  {"cpu_2_threads_s", median(cpu_two)},
                                  {"big_cpu_s", big_cpu_s}};
    std::cout << out.dump(2) << '\n';
    return exit_success;
  }
  std::cout << fmt::format("Jansen leg basin map, theta1 x theta7 slice, {} x {} starts, plain Newton (tolerance 1e-9, "
                           "at most 20 iterations); medians of {} alternating runs.\n\n",
                           side, side, repeats);
  Table table({"measure", "value"});
  table.add_row({"time, 1 thread", fmt::format("{:.3g} s", t1)});
  table.add_row({"time, 2 threads", fmt::format("{:.3g} s", t2)});
  table.add_row({"solves per second, 1 thread", fmt::format("{:.3g}", solves / t1)});
  table.add_row({"solves per second, 2 threads", fmt::format("{:.3g}", solves / t2)});
  table.add_row({"speed-up, 2 threads vs 1", fmt::format("{:.2f}x", t1 / t2)});
  table.add_row({"time per basin solve (1 thread)", fmt::format("{:.3g} us", solve_s * 1e6)});
  table.add_row({"iterations per basin solve", fmt::format("{:.2f}", basin_iterations)});
  table.add_row({"time per crank-sweep pose", fmt::format("{:.3g} us", pose_s * 1e6)});
  table.add_row({"iterations per crank-sweep pose", fmt::format("{:.2f}", sweep_iterations / 360.0)});
  table.add_row({"basin solve / sweep pose", fmt::format("{:.1f}x", solve_s / pose_s)});
  table.add_row({"per iteration: basin / sweep",
                 fmt::format("{:.2f}x", (solve_s / basin_iterations) / (pose_s / (sweep_iterations / 360.0)))});
  table.add_row({"CPU time, 1 thread / 2 threads", fmt::format("{:.3g} s / {:.3g} s", median(cpu_one), median(cpu_two))});
  table.add_row({fmt::format("{} x {} map, {} threads", big, big, cores), fmt::format("{:.3g} s", big_s)});
  table.add_row({fmt::format("{} x {} map, CPU time (all threads)", big, big), fmt::format("{:.3g} s", big_cpu_s)});
  table.print(std::cout);
  std::cout << fmt::format("\nTargets:\n  {0} x {0} map:        {1:.3g} s      (target < 10 s for 1000 x 1000: {2})\n", big,
                           big_s, big == 1000 ? (big_s < 10.0 ? "met" : "NOT met") : "not measured with --quick")
            << fmt::format("  speed-up on 2 threads: {:.2f}x    (target >= 1.8x: {})\n", t1 / t2,
                           t1 / t2 >= 1.8 ? "met" : "NOT met");
  return exit_success;
}

}  // namespace numlab::cli
