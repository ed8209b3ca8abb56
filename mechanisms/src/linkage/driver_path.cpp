#include "numlab/mechanisms/linkage/driver_path.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "numlab/linalg/matrix_file.hpp"
#include "numlab/mechanisms/linkage/linkage_conditioning.hpp"

namespace numlab::mechanisms {

namespace {

constexpr std::size_t max_path_rows = 100000;

std::string trimmed(std::string_view text) {
  const auto first = text.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  const auto last = text.find_last_not_of(" \t\r");
  return std::string(text.substr(first, last - first + 1));
}

// One finite number, the whole field, or nullopt.
std::optional<double> number_in(const std::string& field) {
  const char* begin = field.data() + (field.rfind('+', 0) == 0 ? 1 : 0);
  const char* end = field.data() + field.size();
  double value = 0.0;
  const auto [stop, error] = std::from_chars(begin, end, value);
  if (error != std::errc() || stop != end || begin == end || !std::isfinite(value)) return std::nullopt;
  return value;
}

std::string shown(const std::string& field) {
  std::string out;
  for (char c : field.substr(0, 40)) out += (c >= ' ' && c <= '~') ? c : '?';
  return "'" + out + "'";
}

}  // namespace

std::vector<DriverPathPoint> parse_driver_path(const std::string& text, const std::string& file) {
  std::vector<DriverPathPoint> path;
  std::istringstream lines(text);
  std::string line;
  bool header = false;
  for (int number = 1; std::getline(lines, line); ++number) {
    const auto fail = [&](const std::string& problem) {
      throw std::invalid_argument(fmt::format("{}:{}: {}", file, number, problem));
    };
    const std::string content = trimmed(line);
    if (content.empty() || content[0] == '#') continue;
    std::vector<std::string> fields;
    std::istringstream cells(content);
    for (std::string cell; std::getline(cells, cell, ',');) fields.push_back(trimmed(cell));
    if (content.back() == ',') fields.emplace_back();
    if (fields.size() != 2) fail(fmt::format("{} fields, a driver path has two per row (first driver, second driver)", fields.size()));
    if (!header) {
      header = true;
      if (!number_in(fields[0]) && !number_in(fields[1])) continue;  // the header of two names
      fail("no header: the first row must name the two drivers, e.g. 'crank_deg,crank2_deg'");
    }
    const auto first = number_in(fields[0]), second = number_in(fields[1]);
    if (!first) fail(fmt::format("the first driver's value {} is not a finite number", shown(fields[0])));
    if (!second) fail(fmt::format("the second driver's value {} is not a finite number", shown(fields[1])));
    if (path.size() == max_path_rows) fail(fmt::format("more than {} rows", max_path_rows));
    path.push_back({*first, *second});
  }
  if (path.empty()) throw std::invalid_argument(file + ": no rows: a driver path needs a header and at least one row");
  return path;
}

std::vector<DriverPathPoint> read_driver_path(const std::string& file) {
  return parse_driver_path(linalg::read_text_file(file), file);
}

LinkageSweep solve_driver_path(LinkageModel& model, const LinkageSolver& solver, const std::vector<DriverPathPoint>& path) {
  if (!model.has_second_driver()) throw std::invalid_argument("a driver path needs a mechanism with two drivers");
  const bool first_angle = model.description().driver.angle(), second_angle = model.description().second_driver->angle();
  const double first_step = first_angle ? 2.0 : 0.02 * solver.size();
  const double second_step = second_angle ? 2.0 : 0.02 * solver.size();
  LinkageSweep sweep;
  sweep.status = Status::converged;
  Eigen::VectorXd q = solver.reference();
  DriverPathPoint at{model.driver_to_user(solver.reference_driver()), model.second_driver()};
  std::vector<int> previous_signature = solver.reference_signature();
  for (const DriverPathPoint& target : path) {
    // 1. Sub-steps from the last good pose to this row.
    const double span = std::max(std::abs(target.first - at.first) / first_step, std::abs(target.second - at.second) / second_step);
    const int steps = std::max(1, static_cast<int>(std::ceil(std::min(span, 1e6))));
    LinkageSolution solution{q, {}, -1};
    for (int k = 1; k <= steps; ++k) {
      const double s = static_cast<double>(k) / steps;
      // 2. The second driver held at its interpolated value, the model solved at the first's.
      model.hold_second_driver(at.second + s * (target.second - at.second));
      solution = solver.solve(model.driver_from_user(at.first + s * (target.first - at.first)), solution.q);
      if (solution.outcome.status != Status::converged) break;
    }
    LinkagePose pose;
    pose.driver = target.first;
    pose.second_driver = target.second;
    pose.q = solution.q;
    pose.outcome = solution.outcome;
    pose.failed_block = solution.failed_block;
    pose.condition = std::numeric_limits<double>::quiet_NaN();
    pose.closed_form_distance = std::numeric_limits<double>::quiet_NaN();
    if (solution.outcome.status != Status::converged) {
      // 4. Not assembled here: reported; the next row starts again from the last good pose.
      if (sweep.status == Status::converged) sweep.status = solution.outcome.status;
      sweep.branch_kept = false;
      model.hold_second_driver(at.second);
      sweep.poses.push_back(std::move(pose));
      continue;
    }
    // 3. Kinematics per unit of the first driver, the second held; conditioning; the branch.
    const double t = model.driver_from_user(target.first);
    linkage_kinematics(model, t, pose.q, pose.velocity, pose.acceleration);
    pose.condition = linkage_condition(model, t, pose.q);
    pose.signature = solver.signature(pose.q, t);
    pose.transmission_deg = solver.transmission_angles(pose.q);
    if (pose.signature != previous_signature) {
      sweep.branch_kept = false;
      sweep.flips.push_back(fmt::format("the branch changed between the path's rows before {:.6g}, {:.6g} and at it",
                                        target.first, target.second));
    }
    pose.branch_kept = sweep.branch_kept;
    previous_signature = pose.signature;
    q = pose.q;
    at = target;
    sweep.poses.push_back(std::move(pose));
  }
  return sweep;
}

}  // namespace numlab::mechanisms
