#pragma once
// The CSV of the seeds' hand-coded linkages (numlab mechanism jansen|jansen10|mustang --format csv),
// here so that the command and the linkage page (which embeds these very numbers) share one writer.

#include <ostream>

#include "numlab/mechanisms/jansen_solvers.hpp"
#include "numlab/mechanisms/mustang_sweep.hpp"

namespace numlab::cli {

// |dF / d theta_i| at a pose, from the 8-equation model's rates (NaN where they do not solve).
double jansen_foot_speed(mechanisms::JansenModel model, const mechanisms::JansenPose& pose);

// crank_deg, the model's angles, x_J and y_J of every joint, iterations, residual_inf, status, then
// the Jansen leg's foot_speed or the Mustang's condition.
void print_jansen_csv(std::ostream& out, mechanisms::JansenModel model, const mechanisms::JansenSweep& sweep);
void print_mustang_csv(std::ostream& out, const mechanisms::MustangSweep& sweep);

}  // namespace numlab::cli
