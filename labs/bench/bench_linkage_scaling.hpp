#pragma once
// `numlab bench linkage-scaling`: how a description file's sweep grows with its joints. A chain of
// dyads (mechanisms/linkage/dyad_chain.hpp: a four-bar carrying a strip of triangles) of 10, 100
// and 1000 joints (the most a description may have), a 10-pose sweep each (crank 60..69 degrees,
// full Newton on the fast path, every pose's analysis included: velocity, acceleration, kappa(J),
// signature, the closed-form check); the median time per pose, and its ratio to the 10-joint one.

#include <string>
#include <vector>

#include "bench/bench_options.hpp"
#include "output/exit_codes.hpp"
#include "output/files.hpp"

namespace numlab::cli {

struct LinkageScalingRow {
  int joints;
  int unknowns;
  double sweep_s;         // median of the 10-pose sweep
  double per_pose_s;      // sweep_s / 10
  Status status;          // the sweep's
  bool verified;          // every pose within its closed-form bound
  double worst_condition; // the largest kappa(J) over the poses (kappa_2 up to 100 unknowns, else kappa_1 estimated)
};

std::vector<LinkageScalingRow> bench_linkage_scaling(bool quick);

// `numlab bench linkage-scaling [--format json|csv] [--quick]`.
int run_linkage_scaling_bench(const BenchOptions& common, bool quick);

}  // namespace numlab::cli
