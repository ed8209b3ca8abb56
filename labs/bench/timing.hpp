#pragma once
// In-process timing for benchmarks and lab tables: a warm-up run, then repeated runs, and the median.

#include <algorithm>
#include <chrono>
#include <vector>

namespace numlab::cli {

struct TimingPlan {
  int min_runs = 5;            // at least this many timed runs
  int max_runs = 1000;         // at most this many
  double min_total_s = 0.05;   // keep running until this much time has been measured
};

// Median wall time of one call of `work`, in seconds. Calls shorter than the clock can resolve
// well are batched: each timed sample runs `work` enough times to last at least 20 microseconds.
template <typename Work>
double median_time(Work&& work, TimingPlan plan = {}) {
  using Clock = std::chrono::steady_clock;
  auto seconds_for = [&](int calls) {
    const auto begin = Clock::now();
    for (int call = 0; call < calls; ++call) work();
    return std::chrono::duration<double>(Clock::now() - begin).count();
  };
  // Warm-up (caches, lazy allocations, page faults), then choose the batch size. The first
  // measurement of a process warms up for a quarter of a second as well (why: docs/performance.md).
  static bool process_warmed_up = false;
  if (!process_warmed_up) {
    process_warmed_up = true;
    const auto begin = Clock::now();
    while (std::chrono::duration<double>(Clock::now() - begin).count() < 0.25) work();
  }
  int calls_per_sample = 1;
  while (seconds_for(calls_per_sample) < 20e-6 && calls_per_sample < (1 << 20)) calls_per_sample *= 2;

  std::vector<double> times;
  double total = 0.0;
  while (static_cast<int>(times.size()) < plan.max_runs &&
         (static_cast<int>(times.size()) < plan.min_runs || total < plan.min_total_s)) {
    const double elapsed = seconds_for(calls_per_sample);
    times.push_back(elapsed / calls_per_sample);
    total += elapsed;
  }
  std::nth_element(times.begin(), times.begin() + times.size() / 2, times.end());
  return times[times.size() / 2];
}

}  // namespace numlab::cli
