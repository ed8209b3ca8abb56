#pragma once
// One basin map of a named system ("fractal", "four-bar", "jansen"): the slice it runs over, the
// names of its modes, where its solution and the seed's estimates sit on the slice, and the time.
// What `numlab basins`, the lab `basins` and `numlab bench basins` share.

#include <optional>
#include <string>
#include <vector>

#include "numlab/nonlinear/basin_map.hpp"

namespace numlab::basins {

struct BasinRequest {
  std::string system = "fractal";       // fractal | four-bar | jansen
  int columns = 400, rows = 400;
  std::optional<double> u_min, u_max, v_min, v_max;  // default: the system's own slice
  std::string axis_u, axis_v;           // jansen: theta1 ... theta8 (default theta1, theta7)
  bool damped = false;
  int threads = 1;
  std::optional<int> max_iterations;    // default: the system's own
};

struct SliceMark {
  double u, v;
  std::string label;
};

struct BasinRun {
  nonlinear::BasinMap map;
  std::string system, u_name, v_name;
  std::vector<std::string> mode_labels;  // by mode number
  int home_mode = 0;                     // the mode of the marked solution (the seed's, for Jansen)
  std::vector<SliceMark> marks;          // the solution, and the seed's estimates where they exist
  bool toggle_lines = false;             // four-bar: theta3 - theta4 = k pi drawn
  int max_iterations = 0;
  double seconds = 0.0;                  // the map alone
};

const std::vector<std::string>& basin_system_names();
// The names a jansen slice's axes may take: theta1 ... theta8.
const std::vector<std::string>& jansen_axis_names();

// Largest grid side and thread count `numlab basins` accepts.
inline constexpr int max_grid_side = 1000;
inline constexpr int max_threads = 256;

// Throws std::invalid_argument naming the problem (unknown system or axis, grid or threads out of range).
BasinRun run_basins(const BasinRequest& request);

// Counts of a map: converged per mode (unknown roots last), then each failing status.
struct BasinTally {
  std::vector<int> per_mode;  // by mode number
  int unknown = 0;
  int diverged = 0, singular = 0, max_iterations = 0, non_finite = 0, no_progress = 0;
  int total = 0;
};
BasinTally tally(const nonlinear::BasinMap& map, int modes);

// The distance in the slice from (u, v) to the nearest grid point whose start converged to a mode
// other than `mode` (unknown roots included); infinity when there is none.
double distance_to_other_mode(const nonlinear::BasinMap& map, double u, double v, int mode);
// ... and to the nearest grid point that did not converge; infinity when there is none.
double distance_to_failure(const nonlinear::BasinMap& map, double u, double v);

}  // namespace numlab::basins
