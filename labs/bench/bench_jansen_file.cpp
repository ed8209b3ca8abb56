// `numlab bench jansen`'s rows for the Jansen leg read from mechanisms/models/jansen.toml: the same
// linkage as the hand-coded seed-000 model, derived (joint coordinates, 12 unknowns) instead of
// written by hand (8 angles), so the ratio of their times is what generality costs.

#include <numbers>

#include "bench/bench_jansen.hpp"
#include "bench/timing.hpp"
#include "methods/data_dir.hpp"
#include "numlab/mechanisms/jansen_closure.hpp"
#include "numlab/mechanisms/jansen_leg.hpp"
#include "numlab/mechanisms/linkage/linkage_sweep.hpp"

namespace numlab::cli {

std::vector<JansenBenchRow> bench_jansen_file(double tolerance, bool quick) {
  const mechanisms::LinkageModel model(mechanisms::read_linkage_description(models_dir() + "/jansen.toml"));
  const mechanisms::JansenLeg leg;
  // The hand-coded rows' cycle: 360 poses, 1 degree apart, from the seed's crank angle.
  const double start = mechanisms::JansenClosure::seed_crank_angle * 180.0 / std::numbers::pi;
  const TimingPlan plan = quick ? TimingPlan{3, 10, 0.0} : TimingPlan{7, 1000, 0.3};
  std::vector<JansenBenchRow> rows;
  for (const std::string solver : {"full", "sequential", "analytic"}) {
    mechanisms::LinkageSolverOptions options{solver, "gepp", {}};
    options.newton.residual_tolerance = tolerance;
    options.tolerance_relative_to_size = false;  // the hand-coded rows' absolute tolerance
    options.newton.max_iterations = 100;
    const mechanisms::LinkageSolver linkage(model, options);
    const auto cycle = [&] { return mechanisms::solve_linkage_cycle(linkage, start, start + 359.0, 1.0); };
    const mechanisms::LinkageCycle solved = cycle();
    // Untimed: every joint against the hand-coded closed form.
    double error = solved.status == Status::converged ? 0.0 : std::numeric_limits<double>::infinity();
    for (Eigen::Index k = 0; k < solved.q.cols() && solved.status == Status::converged; ++k) {
      const double crank = (start + static_cast<double>(k)) * std::numbers::pi / 180.0;
      const auto exact = leg.closed_form_joints(crank);
      const auto joints = model.positions(solved.q.col(k));
      for (std::size_t j = 0; j < mechanisms::jansen_joint_names.size() && exact; ++j) {
        const int index = model.description().joint_index(mechanisms::jansen_joint_names[j]);
        error = std::max(error, (joints[static_cast<std::size_t>(index)] - (*exact)[j]).norm());
      }
    }
    rows.push_back({"file-" + solver, mechanisms::JansenModel::eight_equations, tolerance, median_time(cycle, plan), error,
                    solved.iterations});
  }
  return rows;
}

}  // namespace numlab::cli
