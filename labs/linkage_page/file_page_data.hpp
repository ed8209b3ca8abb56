#pragma once
// The linkage page of a description file or shipped model: the drawing from the file, the numbers of
// its sweep's CSV (print_linkage_csv: positions, velocities, transmission angles, kappa(J), the
// statics when the file has loads), and the sweep's assembly limits and branch crossings as marks.

#include <nlohmann/json.hpp>
#include <string>

#include "output/linkage_report.hpp"

namespace numlab::cli {

nlohmann::ordered_json file_page_data(const LinkageReport& report, const std::string& name);

}  // namespace numlab::cli
