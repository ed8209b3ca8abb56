#pragma once
// A mechanism with two drivers (mobility 2, a five-bar) moved along a path in driver space
// (`numlab mechanism FILE --drivers PATH.csv`): each row gives both drivers' values, and the pose
// there is solved from the pose before, through sub-steps small enough for continuation.
//
//  1. From the reference pose to the first row, then from each row to the next, in sub-steps of at
//     most 2 degrees (an angle) or 2% of the mechanism's size (a length) in either driver;
//  2. at each sub-step the second driver is held at its interpolated value and the model is solved
//     at the first's, from the sub-step before;
//  3. at each row: velocity and acceleration per unit of the first driver with the second held
//     (J qdot = -Phi_t), kappa(J), the branch signature; a signature that differs from the row
//     before is a branch change (branch_kept false, named in flips);
//  4. a row that does not assemble is reported with its status; the next row is tried again from
//     the last good pose.

#include <string>
#include <vector>

#include "numlab/mechanisms/linkage/linkage_sweep.hpp"

namespace numlab::mechanisms {

// One row of a driver path, in user units (degrees for a crank, length otherwise).
struct DriverPathPoint {
  double first = 0.0;
  double second = 0.0;
};

// Reads a driver path: a CSV file whose first line is a header of two names, then one row per
// pose, two finite numbers each ("# ..." lines and blank lines skipped). At least one row, at most
// 100000. Throws std::invalid_argument "FILE:LINE: problem" (one line) for anything else.
std::vector<DriverPathPoint> read_driver_path(const std::string& file);
std::vector<DriverPathPoint> parse_driver_path(const std::string& text, const std::string& file);

// The poses along the path (LinkagePose::driver the first driver, ::second_driver the second). The
// model's second driver is left held at the path's last row. std::invalid_argument when the model
// has no second driver. Never throws for a row that does not assemble: its pose carries the status.
LinkageSweep solve_driver_path(LinkageModel& model, const LinkageSolver& solver, const std::vector<DriverPathPoint>& path);

}  // namespace numlab::mechanisms
