#pragma once
// The numbers a linkage page (`numlab mechanism ... --html`) scrubs through, as one JSON object
// embedded in the page: the drawing (joints, links, bodies, sliders of a description file), the
// marks on the crank slider (assembly limits, branch crossings), and one array per column of the
// sweep's CSV, parsed from exactly the text `--format csv` prints, so that page and CSV cannot
// disagree. Columns a page needs that the CSV lacks (the built-in models' velocities) are added
// under their own names and listed in "extra_columns".

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "numlab/mechanisms/linkage/linkage_model.hpp"

namespace numlab::cli {

// A mark on the slider: where (driver value, user units), what ("limit", "crossing", "tangency"),
// and a sentence.
struct PageMark {
  double driver = 0.0;
  std::string kind;
  std::string text;
};

struct PageSource {
  const mechanisms::LinkageModel& model;  // the drawing: a file's, or the shipped file of a built-in
  std::string mechanism;                  // the name given on the command line
  std::string title;
  std::string csv;                        // exactly what --format csv prints for this sweep
  std::optional<double> speed_rad_s;      // --speed: Play runs at this crank speed
  std::vector<std::string> notes;         // sentences shown under the scene
  std::vector<PageMark> marks;
};

// The page's data. Throws std::invalid_argument when the CSV has no rows or a joint of the drawing
// has no x_/y_ column.
nlohmann::ordered_json linkage_page_data(const PageSource& source);

// Adds a column the CSV does not have (one value per pose; NaN becomes null).
void add_page_column(nlohmann::ordered_json& data, const std::string& name, const std::vector<double>& values);

}  // namespace numlab::cli
