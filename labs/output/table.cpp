#include "output/table.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace numlab::cli {

namespace {
constexpr std::size_t no_width_limit = 0;
}  // namespace

void Table::print(std::ostream& out) const { print_rows(out, no_width_limit); }

void Table::print_within(std::ostream& out, std::size_t width) const { print_rows(out, width); }

// Every column padded to its widest cell, the first left-aligned and the others right-aligned;
// with a `width`, the last column is left-aligned instead and wrapped to end by that column.
void Table::print_rows(std::ostream& out, std::size_t width) const {
  const bool wrap_last = width != no_width_limit && header_.size() > 1;
  std::vector<std::size_t> widths(header_.size(), 0);
  auto widen = [&](const std::vector<std::string>& row) {
    for (std::size_t j = 0; j < row.size() && j < widths.size(); ++j) widths[j] = std::max(widths[j], row[j].size());
  };
  widen(header_);
  for (const auto& row : rows_) widen(row);
  const std::size_t last = widths.size() - 1;
  if (wrap_last) {
    std::size_t start = 2;
    for (std::size_t j = 0; j < last; ++j) start += widths[j] + 2;
    constexpr std::size_t narrowest = 12;  // below this the last column would be a word per line
    widths[last] = std::min(widths[last], std::max(width > start ? width - start : 0, narrowest));
  }

  auto print_row = [&](const std::vector<std::string>& row) {
    std::string line = "  ";
    for (std::size_t j = 0; j < widths.size(); ++j) {
      const std::string cell = j < row.size() ? row[j] : "";
      if (wrap_last && j == last) {
        const std::size_t start = line.size();
        const std::vector<std::string> lines = wrap_words(cell, widths[j]);
        for (std::size_t k = 0; k < lines.size(); ++k) {
          if (k > 0) line += '\n' + std::string(lines[k].empty() ? 0 : start, ' ');
          line += lines[k];
        }
      } else {
        line += j == 0 ? fmt::format("{:<{}}", cell, widths[j]) : fmt::format("  {:>{}}", cell, widths[j]);
      }
      if (wrap_last && j + 1 == last) line += "  ";
    }
    while (!line.empty() && line.back() == ' ') line.pop_back();
    out << line << '\n';
  };
  print_row(header_);
  std::size_t total = 0;
  for (std::size_t column_width : widths) total += column_width + 2;
  out << "  " << std::string(total - 2, '-') << '\n';
  for (const auto& row : rows_) print_row(row);
}

std::vector<std::string> wrap_words(const std::string& text, std::size_t width) {
  std::vector<std::string> lines;
  std::size_t paragraph_start = 0;
  while (paragraph_start <= text.size()) {
    const std::size_t paragraph_end = std::min(text.find('\n', paragraph_start), text.size());
    std::string line;
    std::size_t position = paragraph_start;
    while (position < paragraph_end) {
      const std::size_t space = std::min(text.find(' ', position), paragraph_end);
      const std::string word = text.substr(position, space - position);
      if (!line.empty() && line.size() + 1 + word.size() > width) {
        lines.push_back(line);
        line.clear();
      }
      if (!word.empty()) line += (line.empty() ? "" : " ") + word;
      position = space + 1;
    }
    lines.push_back(line);
    paragraph_start = paragraph_end + 1;
  }
  return lines;
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
