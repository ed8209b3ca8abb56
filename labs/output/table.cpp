#include "output/table.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace numlab::cli {

void Table::print(std::ostream& out) const {
  std::vector<std::size_t> widths(header_.size(), 0);
  auto widen = [&](const std::vector<std::string>& row) {
    for (std::size_t j = 0; j < row.size() && j < widths.size(); ++j) widths[j] = std::max(widths[j], row[j].size());
  };
  widen(header_);
  for (const auto& row : rows_) widen(row);

  auto print_row = [&](const std::vector<std::string>& row) {
    std::string line = "  ";
    for (std::size_t j = 0; j < widths.size(); ++j) {
      const std::string cell = j < row.size() ? row[j] : "";
      line += j == 0 ? fmt::format("{:<{}}", cell, widths[j]) : fmt::format("  {:>{}}", cell, widths[j]);
    }
    while (!line.empty() && line.back() == ' ') line.pop_back();
    out << line << '\n';
  };
  print_row(header_);
  std::size_t total = 0;
  for (std::size_t width : widths) total += width + 2;
  out << "  " << std::string(total - 2, '-') << '\n';
  for (const auto& row : rows_) print_row(row);
}

std::string Table::csv() const {
  auto append_cell = [](std::string& text, const std::string& cell) {
    if (cell.find_first_of(",\"") == std::string::npos) {
      text += cell;
      return;
    }
    text += '"';
    for (char c : cell) {
      if (c == '"') text += '"';  // a quote inside a quoted cell is doubled
      text += c;
    }
    text += '"';
  };
  auto append_line = [&](std::string& text, const std::vector<std::string>& row) {
    for (std::size_t j = 0; j < row.size(); ++j) {
      if (j > 0) text += ',';
      append_cell(text, row[j]);
    }
    text += '\n';
  };
  std::string text;
  append_line(text, header_);
  for (const auto& row : rows_) append_line(text, row);
  return text;
}

std::string scientific(double value) {
  if (std::isnan(value)) return "-";
  return fmt::format("{:.3g}", value);
}

std::string fixed(double value, int decimals) {
  if (std::isnan(value)) return "-";
  return fmt::format("{:.{}f}", value, decimals);
}

}  // namespace numlab::cli
