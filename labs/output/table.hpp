#pragma once
// A fixed-width text table: a header row, then rows, columns padded to their widest cell.

#include <ostream>
#include <string>
#include <vector>

namespace numlab::cli {

class Table {
 public:
  explicit Table(std::vector<std::string> header) : header_(std::move(header)) {}
  void add_row(std::vector<std::string> row) { rows_.push_back(std::move(row)); }
  void print(std::ostream& out) const;
  // The same, fitted to `width` columns: the last column is left-aligned and its text wrapped at
  // spaces, each further line starting under the column (a '\n' in its cell starts a new line).
  void print_within(std::ostream& out, std::size_t width) const;
  // The same cells as CSV (header line, then rows; cells with commas or quotes are quoted).
  std::string csv() const;
  const std::vector<std::string>& header() const { return header_; }
  const std::vector<std::vector<std::string>>& rows() const { return rows_; }

 private:
  void print_rows(std::ostream& out, std::size_t width) const;
  std::vector<std::string> header_;
  std::vector<std::vector<std::string>> rows_;
};

// The width the listings (`numlab models`, `numlab labs`) fit: a terminal's 80 columns.
constexpr std::size_t terminal_width = 80;

// `text` in lines of at most `width` characters, broken at spaces (a longer word keeps a line of its
// own); a '\n' in it starts a new line.
std::vector<std::string> wrap_words(const std::string& text, std::size_t width);

// Number formats used across tables: 3 significant digits in scientific notation, or "-" for NaN.
std::string scientific(double value);
std::string fixed(double value, int decimals);

}  // namespace numlab::cli
