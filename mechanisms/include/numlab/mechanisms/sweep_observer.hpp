#pragma once
// What a crank sweep (the Jansen leg's or the Mustang's) tells its observer: one record per pose
// solve it attempted, accepted or not. The same record and the same recorder serve both sweeps.

#include <Eigen/Core>
#include <vector>

#include "numlab/mechanisms/pose_solver.hpp"
#include "numlab/solver.hpp"

namespace numlab::mechanisms {

struct SweepPoseRecord {
  double crank_deg;                          // where the pose was solved
  double step_deg;                           // from the last pose the sweep kept
  PoseOutcome outcome;                       // how the solve went
  bool accepted;                             // the sweep kept the pose (converged, on its branch)
  Eigen::Ref<const Eigen::VectorXd> angles;  // where the solve ended (valid during on_step only)
};

// Observers of sweep stepper Sweep (JansenSweepStepper, MustangSweepStepper).
template <typename Sweep>
using SweepObserver = StepObserver<Sweep, SweepPoseRecord>;

// One attempt, kept: the record with its own copy of the angles.
struct SweepAttempt {
  double crank_deg = 0.0, step_deg = 0.0;
  PoseOutcome outcome;
  bool accepted = false;
  Eigen::VectorXd angles;
};

// Keeps every attempt of a sweep, in order (the trace).
template <typename Sweep>
class SweepRecorder : public SweepObserver<Sweep> {
 public:
  StepControl on_step(const Sweep&, const SweepPoseRecord& record) override {
    attempts_.push_back({record.crank_deg, record.step_deg, record.outcome, record.accepted, record.angles});
    return StepControl::proceed;
  }
  const std::vector<SweepAttempt>& attempts() const { return attempts_; }

 private:
  std::vector<SweepAttempt> attempts_;
};

}  // namespace numlab::mechanisms
