// StopReason -> Status: status_of() for every reason, and docs/architecture.md's tables against it.

#include <catch2/catch.hpp>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "numlab/nonlinear/stop_reason.hpp"

using numlab::Status;
using numlab::nonlinear::status_of;
using numlab::nonlinear::StopReason;

namespace {

struct Expected {
  StopReason reason;
  const char* name;
  Status status;
};

// Written out by hand, a second time, on purpose: a change to status_of() must be made here too.
const std::vector<Expected> expected{
    {StopReason::running, "running", Status::running},
    {StopReason::residual_small, "residual_small", Status::converged},
    {StopReason::step_small, "step_small", Status::no_progress},
    {StopReason::iteration_limit, "iteration_limit", Status::max_iterations},
    {StopReason::singular_jacobian, "singular_jacobian", Status::singular},
    {StopReason::non_finite, "non_finite", Status::non_finite},
    {StopReason::diverged, "diverged", Status::diverged},
    {StopReason::no_descent, "no_descent", Status::no_progress},
    {StopReason::no_progress, "no_progress", Status::no_progress},
    {StopReason::inner_limit, "inner_limit", Status::max_iterations},
    {StopReason::inner_step_failed, "inner_step_failed", Status::max_iterations},
    {StopReason::radius_small, "radius_small", Status::no_progress}};

std::string trimmed(const std::string& cell) {
  std::string out;
  for (char c : cell) {
    if (c != '`') out += c;
  }
  const auto first = out.find_first_not_of(' ');
  return first == std::string::npos ? "" : out.substr(first, out.find_last_not_of(' ') - first + 1);
}

// The body rows of the markdown table whose header line starts with `header`, split into cells.
std::vector<std::vector<std::string>> table_after(const std::string& header) {
  std::ifstream doc(NUMLAB_ARCHITECTURE_DOC);
  REQUIRE(doc);
  std::vector<std::vector<std::string>> rows;
  std::string line;
  bool inside = false;
  while (std::getline(doc, line)) {
    if (!inside) {
      inside = line.rfind(header, 0) == 0;
      if (inside) std::getline(doc, line);  // the | --- | line
      continue;
    }
    if (line.empty() || line[0] != '|') break;
    std::vector<std::string> cells;
    std::stringstream split(line.substr(1));
    for (std::string cell; std::getline(split, cell, '|');) cells.push_back(trimmed(cell));
    rows.push_back(cells);
  }
  return rows;
}

}  // namespace

TEST_CASE("status_of maps every StopReason to its status", "[stop_reason]") {
  REQUIRE(expected.size() == numlab::nonlinear::stop_reasons.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    INFO(expected[i].name);
    CHECK(numlab::nonlinear::stop_reasons[i] == expected[i].reason);
    CHECK(status_of(expected[i].reason) == expected[i].status);
  }
  // Only a finished iteration has a verdict, and only the residual test says converged.
  for (const StopReason reason : numlab::nonlinear::stop_reasons) {
    CHECK((status_of(reason) == Status::running) == (reason == StopReason::running));
    CHECK((status_of(reason) == Status::converged) == (reason == StopReason::residual_small));
  }
}

TEST_CASE("docs/architecture.md's StopReason table is status_of", "[stop_reason]") {
  const auto rows = table_after("| `StopReason` | status |");
  REQUIRE(rows.size() == expected.size());
  std::map<std::string, Status> documented;
  for (const auto& row : rows) {
    REQUIRE(row.size() >= 2);
    documented[row[0]] = [&] {
      for (const Status s : {Status::running, Status::converged, Status::max_iterations, Status::singular,
                             Status::non_finite, Status::diverged, Status::no_progress, Status::cannot_assemble}) {
        if (numlab::to_string(s) == row[1]) return s;
      }
      FAIL("unknown status '" << row[1] << "' for " << row[0]);
      return Status::running;
    }();
  }
  for (const auto& e : expected) {
    INFO(e.name);
    REQUIRE(documented.count(e.name) == 1);
    CHECK(documented.at(e.name) == status_of(e.reason));
  }
}

TEST_CASE("docs/architecture.md's stop tests end as status_of says", "[stop_reason]") {
  const auto rows = table_after("| test | condition | ends with |");
  int checked = 0;
  for (const auto& row : rows) {
    for (const auto& e : expected) {
      if (row.size() < 3 || row[0] != e.name) continue;
      INFO(row[0]);
      CHECK(row[2] == numlab::to_string(status_of(e.reason)));
      ++checked;
    }
  }
  CHECK(checked == 3);  // residual_small, step_small, diverged
}
