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
  // The same cells as CSV (header line, then rows; cells with commas or quotes are quoted).
  std::string csv() const;
  const std::vector<std::string>& header() const { return header_; }
  const std::vector<std::vector<std::string>>& rows() const { return rows_; }

 private:
  std::vector<std::string> header_;
  std::vector<std::vector<std::string>> rows_;
};

// Number formats used across tables: 3 significant digits in scientific notation, or "-" for NaN.
std::string scientific(double value);
std::string fixed(double value, int decimals);

}  // namespace numlab::cli
