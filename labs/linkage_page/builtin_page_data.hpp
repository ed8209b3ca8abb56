#pragma once
// The linkage page of a built-in model (jansen, jansen10, mustang): drawn with the links and bodies
// of its shipped file (jansen.toml, mustang.toml: the same joints under the same names), with the
// numbers of its own CSV, and per pose, from the file's joint-coordinate model at the built-in's
// joints, what that CSV lacks: every joint's velocity (J qdot = -Phi_t, per radian of crank), each
// dyad's transmission angle, and kappa_2(J) where the CSV has no condition column.

#include <nlohmann/json.hpp>
#include <string>

#include "numlab/mechanisms/jansen_solvers.hpp"
#include "numlab/mechanisms/mustang_sweep.hpp"

namespace numlab::cli {

// `origin` says where the numbers come from, e.g. "numlab mechanism jansen --format csv".
nlohmann::ordered_json jansen_page_data(const std::string& name, mechanisms::JansenModel model,
                                        const mechanisms::JansenSweep& sweep, const std::string& origin);

// The sweep asked for (start, stop in degrees) is said on the page: its poses are only those that assembled.
nlohmann::ordered_json mustang_page_data(const mechanisms::MustangSweep& sweep, double start_deg, double stop_deg,
                                         const std::string& origin);

}  // namespace numlab::cli
