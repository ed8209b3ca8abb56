#pragma once
// What `numlab mechanism FILE` prints: the derived model (--explain), and a sweep's report as text,
// CSV (columns x_J, y_J, vx_J, vy_J, ax_J, ay_J per joint) or JSON.

#include <nlohmann/json.hpp>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "output/exit_codes.hpp"
#include "output/format.hpp"
#include "numlab/mechanisms/linkage/crank_analysis.hpp"
#include "numlab/mechanisms/linkage/link_motion.hpp"
#include "numlab/mechanisms/linkage/linkage_sweep.hpp"
#include "numlab/nonlinear/jacobian_check.hpp"

namespace numlab::cli {

// The exact Jacobian against finite differences over the solved poses (--check-jacobian).
struct JacobianReport {
  int poses = 0;
  double driver = 0.0;                 // where the worst entry was
  nonlinear::JacobianCheck worst;      // the pose with the largest relative error
};

// Velocities and accelerations against finite differences of positions at a few poses.
struct DerivativeReport {
  int poses = 0, unsolved = 0;
  int singular = 0;            // poses on a crossing or fold: not checked (their kinematics are differences already)
  int ill_conditioned = 0;     // poses with kappa(J) > 1e5 but every block regular: not checked either
  double velocity = 0.0;       // worst |qdot - central difference| / (|qdot| + size)
  double acceleration = 0.0;   // worst |qddot - 7-point stencil| / (|qddot| + size)
  std::string failure;         // the first pose beyond the tolerance, in words; empty when none
};

struct LinkageReport {
  const mechanisms::LinkageModel& model;
  const mechanisms::LinkageSolver& solver;
  const mechanisms::LinkageSweep& sweep;
  double time_s = 0.0;
  DerivativeReport derivatives;
  std::optional<JacobianReport> jacobian;
  Status status = Status::converged;  // the sweep's, or no_progress when the branch flipped
  std::vector<std::string> warnings{};  // the authoring checks' "FILE:LINE: text" lines
  std::optional<mechanisms::LinkageOutput> output{};  // --output or the file's `output`: its velocity ratio
  std::optional<double> speed_rad_s{};                // --speed: link rates per second too
};

// The transmission-angle window: a dyad outside it transmits force poorly.
inline constexpr double transmission_low_deg = 40.0, transmission_high_deg = 140.0;

void print_explanation(std::ostream& out, const mechanisms::LinkageModel& model, Format format);
void print_linkage_text(std::ostream& out, const LinkageReport& report, const std::string& file);
void print_linkage_csv(std::ostream& out, const LinkageReport& report);
nlohmann::ordered_json linkage_json(const LinkageReport& report, const nlohmann::ordered_json* trace);
nlohmann::ordered_json pose_trace_json(const mechanisms::LinkagePose& pose);
// --analyse: the four-bar or slider-crank analysis (crank_analysis.hpp), as text or JSON.
void print_crank_analysis(std::ostream& out, const mechanisms::LinkageModel& model, const mechanisms::CrankAnalysis& analysis,
                          const std::string& file, Format format);

}  // namespace numlab::cli
