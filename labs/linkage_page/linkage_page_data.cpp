#include "linkage_page/linkage_page_data.hpp"

#include <cmath>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

#include "numlab/mechanisms/linkage/link_motion.hpp"
#include "output/linkage_report.hpp"

namespace numlab::cli {

namespace {

using nlohmann::ordered_json;
using mechanisms::LinkageDescription;

std::vector<std::string> split(const std::string& line, char separator) {
  std::vector<std::string> cells;
  std::string cell;
  std::istringstream in(line);
  while (std::getline(in, cell, separator)) cells.push_back(cell);
  if (!line.empty() && line.back() == separator) cells.emplace_back();
  return cells;
}

// A cell as a number, when the whole cell is one ("nan" and "inf" included).
std::optional<double> number_in(const std::string& cell) {
  if (cell.empty()) return std::nullopt;
  char* end = nullptr;
  const double value = std::strtod(cell.c_str(), &end);
  if (end != cell.c_str() + cell.size()) return std::nullopt;
  return value;
}

ordered_json json_number(double value) { return std::isfinite(value) ? ordered_json(value) : ordered_json(nullptr); }

// 1. The CSV's columns: a column of numbers (null where not finite), or of words (status, yes/no).
ordered_json columns_of(const std::string& csv, std::vector<std::string>& names) {
  std::istringstream in(csv);
  std::string line;
  if (!std::getline(in, line)) throw std::invalid_argument("the linkage page: the sweep's CSV is empty");
  names = split(line, ',');
  std::vector<std::vector<std::string>> cells(names.size());
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    const auto row = split(line, ',');
    if (row.size() != names.size()) throw std::invalid_argument("the linkage page: a CSV row's cells do not match its header");
    for (std::size_t c = 0; c < row.size(); ++c) cells[c].push_back(row[c]);
  }
  if (cells.empty() || cells[0].empty()) throw std::invalid_argument("the linkage page: the sweep has no pose");
  ordered_json columns = ordered_json::object();
  for (std::size_t c = 0; c < names.size(); ++c) {
    bool numeric = true;
    for (const auto& cell : cells[c]) numeric = numeric && number_in(cell).has_value();
    ordered_json column = ordered_json::array();
    for (const auto& cell : cells[c]) column.push_back(numeric ? json_number(*number_in(cell)) : ordered_json(cell));
    columns[names[c]] = std::move(column);
  }
  return columns;
}

const char* driver_kind(mechanisms::DriverKind kind) {
  switch (kind) {
    case mechanisms::DriverKind::crank: return "crank";
    case mechanisms::DriverKind::slider: return "slider";
    case mechanisms::DriverKind::actuator: return "actuator";
    case mechanisms::DriverKind::motor: return "motor";
  }
  return "crank";
}

// 2. The drawing: joints (ground ones with their place), links, bodies, sliders, the driver.
ordered_json drawing_of(const LinkageDescription& d) {
  ordered_json joints = ordered_json::array(), links = ordered_json::array(), bodies = ordered_json::array(),
               sliders = ordered_json::array();
  for (const auto& joint : d.joints) joints.push_back({{"name", joint.name}, {"ground", joint.ground}});
  for (const auto& link : d.links) links.push_back({link.first, link.second});
  for (const auto& body : d.bodies) bodies.push_back({{"name", body.name}, {"joints", body.joints}});
  for (const auto& slider : d.sliders) {
    ordered_json s = {{"joint", slider.joint}, {"through", {slider.through.x(), slider.through.y()}}, {"angle_deg", slider.angle_deg}};
    if (slider.on_link()) s["line"] = {slider.line_from, slider.line_to};
    sliders.push_back(std::move(s));
  }
  return {{"joints", joints}, {"links", links}, {"bodies", bodies}, {"sliders", sliders},
          {"driver", {{"kind", driver_kind(d.driver.kind)},
                      {"pivot", d.driver.pivot},
                      {"joint", d.driver.joint},
                      {"from", d.driver.from},
                      {"slider", d.driver.slider}}}};
}

// 3. The loads, as the file gives them: a force at a joint (N), a mass at a joint with its weight
// (0, -m g) N, a torque (N x length unit, counter-clockwise +) on a link or body and that item's joints.
ordered_json loads_of(const LinkageDescription& d) {
  const auto lines = mechanisms::link_lines(d);
  ordered_json loads = ordered_json::array();
  for (const auto& load : d.loads) {
    if (load.kind == mechanisms::LoadKind::torque) {
      const auto& line = lines.at(static_cast<std::size_t>(load.line));
      const std::size_t body = static_cast<std::size_t>(load.line) - d.links.size();  // bodies follow the links
      const std::vector<int> on = line.body ? d.bodies.at(body).joints : std::vector<int>{line.from, line.to};
      loads.push_back({{"kind", "torque"}, {"link", line.name}, {"joints", on}, {"torque", load.torque}});
    } else if (load.kind == mechanisms::LoadKind::mass) {
      loads.push_back({{"kind", "mass"}, {"joint", load.joint}, {"mass", load.mass}, {"gravity", d.gravity},
                       {"force", {0.0, -load.mass * d.gravity}}});
    } else {
      loads.push_back({{"kind", "force"}, {"joint", load.joint}, {"force", {load.force.x(), load.force.y()}}});
    }
  }
  return loads;
}

}  // namespace

nlohmann::ordered_json linkage_page_data(const PageSource& source) {
  std::vector<std::string> names;
  ordered_json columns = columns_of(source.csv, names);
  const LinkageDescription& d = source.model.description();
  for (const auto& joint : d.joints) {
    if (!columns.contains("x_" + joint.name) || !columns.contains("y_" + joint.name)) {
      throw std::invalid_argument("the linkage page: the CSV has no x_" + joint.name + " or y_" + joint.name);
    }
  }
  ordered_json data = {{"format", "numlab linkage page 1"},
                       {"mechanism", source.mechanism},
                       {"title", source.title},
                       {"notes", source.notes},
                       {"driver_column", names.front()},
                       {"speed_rad_s", source.speed_rad_s ? ordered_json(*source.speed_rad_s) : ordered_json(nullptr)}};
  data.update(drawing_of(d));
  data["loads"] = loads_of(d);
  data["transmission_window"] = {transmission_low_deg, transmission_high_deg};
  ordered_json marks = ordered_json::array();
  for (const auto& mark : source.marks) marks.push_back({{"driver", mark.driver}, {"kind", mark.kind}, {"text", mark.text}});
  data["marks"] = std::move(marks);
  data["csv_columns"] = names;
  data["extra_columns"] = ordered_json::array();
  data["columns"] = std::move(columns);
  return data;
}

void add_page_column(nlohmann::ordered_json& data, const std::string& name, const std::vector<double>& values) {
  ordered_json column = ordered_json::array();
  for (const double value : values) column.push_back(json_number(value));
  data["extra_columns"].push_back(name);
  data["columns"][name] = std::move(column);
}

}  // namespace numlab::cli
