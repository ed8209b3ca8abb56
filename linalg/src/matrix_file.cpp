#include "numlab/linalg/matrix_file.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace numlab::linalg {

namespace {

[[noreturn]] void fail(const std::string& source, int line, const std::string& what) {
  throw std::invalid_argument(source + ":" + std::to_string(line) + ": " + what);
}

// Splits one line (comment already removed) on whitespace and commas, and parses each number.
std::vector<double> parse_row(const std::string& line, const std::string& source, int line_number) {
  std::vector<double> row;
  std::size_t position = 0;
  while (position < line.size()) {
    const std::size_t begin = line.find_first_not_of(" \t\r,", position);
    if (begin == std::string::npos) break;
    std::size_t end = line.find_first_of(" \t\r,", begin);
    if (end == std::string::npos) end = line.size();
    const std::string token = line.substr(begin, end - begin);
    double value = 0.0;
    const char* first = token.data();
    if (!token.empty() && token[0] == '+') ++first;
    const auto [stop, error] = std::from_chars(first, token.data() + token.size(), value);
    if (error == std::errc::result_out_of_range) fail(source, line_number, "'" + token + "' is out of range");
    if (error != std::errc() || stop != token.data() + token.size()) {
      fail(source, line_number, "'" + token + "' is not a number");
    }
    if (!std::isfinite(value)) fail(source, line_number, "'" + token + "' is not a finite number");
    row.push_back(value);
    position = end;
  }
  return row;
}

}  // namespace

Eigen::MatrixXd parse_matrix(const std::string& text, const std::string& source) {
  std::vector<std::vector<double>> rows;
  std::istringstream lines(text);
  std::string line;
  int line_number = 0;
  while (std::getline(lines, line)) {
    ++line_number;
    line = line.substr(0, line.find('#'));
    std::vector<double> row = parse_row(line, source, line_number);
    if (row.empty()) continue;
    if (!rows.empty() && row.size() != rows.front().size()) {
      fail(source, line_number,
           "row has " + std::to_string(row.size()) + " numbers, earlier rows have " + std::to_string(rows.front().size()));
    }
    rows.push_back(std::move(row));
  }
  if (rows.empty()) throw std::invalid_argument(source + ": no numbers found");

  Eigen::MatrixXd matrix(rows.size(), rows.front().size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    for (std::size_t j = 0; j < rows[i].size(); ++j) matrix(i, j) = rows[i][j];
  }
  return matrix;
}

Eigen::MatrixXd read_matrix_file(const std::string& path) {
  std::ifstream file(path);
  if (!file) throw std::invalid_argument(path + ": cannot open file");
  std::ostringstream contents;
  contents << file.rdbuf();
  return parse_matrix(contents.str(), path);
}

Eigen::VectorXd read_vector_file(const std::string& path) {
  const Eigen::MatrixXd values = read_matrix_file(path);
  if (values.cols() != 1 && values.rows() != 1) {
    throw std::invalid_argument(path + ": a vector must be one row or one column, got " +
                                std::to_string(values.rows()) + "x" + std::to_string(values.cols()));
  }
  return Eigen::Map<const Eigen::VectorXd>(values.data(), values.size());
}

}  // namespace numlab::linalg
