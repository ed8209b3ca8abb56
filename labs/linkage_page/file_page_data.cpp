#include "linkage_page/file_page_data.hpp"

#include <fmt/format.h>

#include <cmath>
#include <sstream>

#include "linkage_page/linkage_page_data.hpp"
#include "output/driver_units.hpp"
#include "numlab/mechanisms/linkage/linkage_blocks.hpp"

namespace numlab::cli {

namespace {

std::string unit_of(const mechanisms::LinkageModel& model) { return model.description().driver.angle() ? " deg" : ""; }

// What the velocities are per: a radian of the driver's angle, or a unit of its travel or length.
std::string per_driver(const mechanisms::LinkageModel& model) { return velocity_per(model.driver_kind()); }

std::string block_text(const LinkageReport& r, int block) {
  if (block < 0 || static_cast<std::size_t>(block) >= r.solver.blocks().size()) return "no block named";
  return fmt::format("block {} ({})", block + 1, mechanisms::describe_block(r.model, r.solver.blocks()[static_cast<std::size_t>(block)]));
}

// Each limit and each crossing or tangency of the sweep, in words.
std::vector<PageMark> marks_of(const LinkageReport& r) {
  std::vector<PageMark> marks;
  const std::string unit = unit_of(r.model);
  for (const auto& limit : r.sweep.limits) {
    if (limit.assembles_beyond) {
      marks.push_back({limit.driver, "failure",
                       fmt::format("the solver failed {} {:.2f}{}, yet the mechanism assembles there: not an assembly limit",
                                   limit.upper ? "past" : "before", limit.driver, unit)});
      continue;
    }
    marks.push_back({limit.driver, "limit",
                     fmt::format("{} assembly limit {:.2f}{}: {} cannot close", limit.upper ? "upper" : "lower", limit.driver,
                                 unit, block_text(r, limit.block))});
  }
  for (const auto& crossing : r.sweep.crossings) {
    marks.push_back({crossing.driver, crossing.tangency ? "tangency" : "crossing",
                     fmt::format("{} at {:.2f}{}: {}'s two solutions meet (J singular); the sweep follows the {} branch",
                                 crossing.tangency ? "tangency" : "branch crossing", crossing.driver, unit,
                                 block_text(r, crossing.block), crossing.switched ? "other" : "smooth")});
  }
  return marks;
}

}  // namespace

nlohmann::ordered_json file_page_data(const LinkageReport& report, const std::string& name) {
  std::ostringstream csv;
  print_linkage_csv(csv, report);
  const auto& d = report.model.description();
  std::vector<std::string> notes{
      fmt::format("The numbers of numlab mechanism {} --format csv (solver {}); velocities are per {}.", name,
                  report.solver.options().solver, per_driver(report.model))};
  if (!d.loads.empty()) notes.push_back("The file has loads: the driver's torque (or force) holding them in equilibrium is shown per pose.");
  const PageSource source{report.model, name, d.title.empty() ? d.name : d.title, csv.str(), report.speed_rad_s, notes,
                          marks_of(report)};
  return linkage_page_data(source);
}

}  // namespace numlab::cli
