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

// What the benchmark measured, in the order it reports it.
struct BasinsMeasurement {
  int side = 0, repeats = 0;
  double solves = 0.0;                      // starts in the map (side x side)
  double t1 = 0.0, t2 = 0.0;                // median wall time on 1 and 2 threads
  double cpu_one = 0.0, cpu_two = 0.0;      // median CPU time of the process, 1 and 2 threads
  double basin_iterations = 0.0;            // Newton iterations per start
  double solve_s = 0.0, pose_s = 0.0;       // one basin solve, one crank-sweep pose
  int sweep_iterations = 0;                 // over the 360 poses
  int big = 0, cores = 0;                   // the big map's side, on every core
  double big_s = 0.0, big_cpu_s = 0.0;
};

double cpu_seconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

// 1. Threads 1 and 2, alternating, on the same map.
//    Beside the wall times, the CPU time of the whole process over each run (all threads): on a
//    machine shared with other work the wall-clock speed-up shows the sharing, the CPU times show
//    whether the threads themselves add work.
void measure_threads(BasinsMeasurement& m) {
  std::vector<double> one, two, cpu_one, cpu_two;
  nonlinear::BasinMap map;
  for (int run = 0; run < m.repeats; ++run) {
    double cpu = cpu_seconds();
    const auto single = basins::run_basins(jansen_map(m.side, 1));
    cpu_one.push_back(cpu_seconds() - cpu);
    one.push_back(single.seconds);
    cpu = cpu_seconds();
    two.push_back(basins::run_basins(jansen_map(m.side, 2)).seconds);
    cpu_two.push_back(cpu_seconds() - cpu);
    map = single.map;
  }
  m.solves = static_cast<double>(m.side) * m.side;
  m.t1 = median(one);
  m.t2 = median(two);
  m.basin_iterations = static_cast<double>(iterations_of(map)) / m.solves;
  m.cpu_one = median(cpu_one);
  m.cpu_two = median(cpu_two);
}

// 2. One pose of the crank sweep: full Newton (GEPP) on the same closure, same tolerance and limit.
void measure_sweep_pose(BasinsMeasurement& m, bool quick) {
  nonlinear::NewtonOptions options;
  options.max_iterations = 20;
  const auto solver = mechanisms::make_jansen_solver(mechanisms::JansenModel::eight_equations, "full", "gepp", options);
  const double start = mechanisms::JansenClosure::seed_crank_angle * 180.0 / std::numbers::pi;
  const auto cycle = [&] {
    return mechanisms::solve_crank_sweep(mechanisms::JansenModel::eight_equations, *solver, start, start + 359.0, 1.0);
  };
  for (const auto& outcome : cycle().outcomes) m.sweep_iterations += outcome.iterations;
  m.pose_s = median_time(cycle, quick ? TimingPlan{3, 10, 0.0} : TimingPlan{7, 1000, 0.3}) / 360.0;
  m.solve_s = m.t1 / m.solves;
}

// 3. The 1000 x 1000 map on every core (a 400 x 400 one with --quick).
void measure_big_map(BasinsMeasurement& m, bool quick) {
  m.big = quick ? 400 : 1000;
  std::vector<double> big_times, big_cpu;
  for (int run = 0; run < (quick ? 1 : 3); ++run) {
    const double cpu = cpu_seconds();
    big_times.push_back(basins::run_basins(jansen_map(m.big, m.cores)).seconds);
    big_cpu.push_back(cpu_seconds() - cpu);
  }
  m.big_s = median(big_times);
  m.big_cpu_s = median(big_cpu);
}

void print_json(const BasinsMeasurement& m) {
  nlohmann::ordered_json out = {{"benchmark", "basins"},
                                {"grid", m.side},
                                {"runs", m.repeats},
                                {"time_1_thread_s", m.t1},
                                {"time_2_threads_s", m.t2},
                                {"solves_per_second_1_thread", m.solves / m.t1},
                                {"solves_per_second_2_threads", m.solves / m.t2},
                                {"speed_up_2_threads", m.t1 / m.t2},
                                {"iterations_per_solve", m.basin_iterations},
                                {"time_per_solve_s", m.solve_s},
                                {"time_per_sweep_pose_s", m.pose_s},
                                {"iterations_per_sweep_pose", m.sweep_iterations / 360.0},
                                {"solve_to_pose_ratio", m.solve_s / m.pose_s},
                                {"big_grid", m.big},
                                {"big_threads", m.cores},
                                {"big_time_s", m.big_s},
                                {"cpu_1_thread_s", m.cpu_one},
                                {"cpu_2_threads_s", m.cpu_two},
                                {"big_cpu_s", m.big_cpu_s}};
  std::cout << out.dump(2) << '\n';
}

void print_text(const BasinsMeasurement& m) {
  std::cout << fmt::format("Jansen leg basin map, theta1 x theta7 slice, {} x {} starts, plain Newton (tolerance 1e-9, "
                           "at most 20 iterations); medians of {} alternating runs.\n\n",
                           m.side, m.side, m.repeats);
  Table table({"measure", "value"});
  table.add_row({"time, 1 thread", fmt::format("{:.3g} s", m.t1)});
  table.add_row({"time, 2 threads", fmt::format("{:.3g} s", m.t2)});
  table.add_row({"solves per second, 1 thread", fmt::format("{:.3g}", m.solves / m.t1)});
  table.add_row({"solves per second, 2 threads", fmt::format("{:.3g}", m.solves / m.t2)});
  table.add_row({"speed-up, 2 threads vs 1", fmt::format("{:.2f}x", m.t1 / m.t2)});
  table.add_row({"time per basin solve (1 thread)", fmt::format("{:.3g} us", m.solve_s * 1e6)});
  table.add_row({"iterations per basin solve", fmt::format("{:.2f}", m.basin_iterations)});
  table.add_row({"time per crank-sweep pose", fmt::format("{:.3g} us", m.pose_s * 1e6)});
  table.add_row({"iterations per crank-sweep pose", fmt::format("{:.2f}", m.sweep_iterations / 360.0)});
  table.add_row({"basin solve / sweep pose", fmt::format("{:.1f}x", m.solve_s / m.pose_s)});
  table.add_row({"per iteration: basin / sweep",
                 fmt::format("{:.2f}x", (m.solve_s / m.basin_iterations) / (m.pose_s / (m.sweep_iterations / 360.0)))});
  table.add_row({"CPU time, 1 thread / 2 threads", fmt::format("{:.3g} s / {:.3g} s", m.cpu_one, m.cpu_two)});
  table.add_row({fmt::format("{} x {} map, {} threads", m.big, m.big, m.cores), fmt::format("{:.3g} s", m.big_s)});
  table.add_row({fmt::format("{} x {} map, CPU time (all threads)", m.big, m.big), fmt::format("{:.3g} s", m.big_cpu_s)});
  table.print(std::cout);
  std::cout << fmt::format("\nTargets:\n  {0} x {0} map:        {1:.3g} s      (target < 10 s for 1000 x 1000: {2})\n", m.big,
                           m.big_s, m.big == 1000 ? (m.big_s < 10.0 ? "met" : "NOT met") : "not measured with --quick")
            << fmt::format("  speed-up on 2 threads: {:.2f}x    (target >= 1.8x: {})\n", m.t1 / m.t2,
                           m.t1 / m.t2 >= 1.8 ? "met" : "NOT met");
}

}  // namespace

int run_basins_bench(const BenchOptions& common, bool quick) {
  BasinsMeasurement m;
  m.cores = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  m.side = quick ? 100 : 300;
  m.repeats = quick ? 3 : 7;
  measure_threads(m);
  measure_sweep_pose(m, quick);
  measure_big_map(m, quick);
  if (common.format == Format::json) {
    print_json(m);
  } else {
    print_text(m);
  }
  return exit_success;
}

}  // namespace numlab::cli
