#include "numlab/fitting/data_set.hpp"

#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace numlab::fitting {

namespace {

std::vector<std::string> read_lines(const std::string& path) {
  std::ifstream file(path);
  if (!file) throw std::invalid_argument(path + ": cannot open the file (missing or unreadable)");
  std::vector<std::string> lines;
  for (std::string line; std::getline(file, line);) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines.push_back(line);
  }
  return lines;
}

std::vector<std::string> split(const std::string& line, char separator) {
  std::vector<std::string> cells;
  std::stringstream stream(line);
  for (std::string cell; std::getline(stream, cell, separator);) {
    const auto first = cell.find_first_not_of(" \t");
    const auto last = cell.find_last_not_of(" \t");
    cells.push_back(first == std::string::npos ? "" : cell.substr(first, last - first + 1));
  }
  if (!line.empty() && line.back() == separator) cells.emplace_back();
  return cells;
}

std::vector<std::string> words(const std::string& line) {
  std::vector<std::string> tokens;
  std::stringstream stream(line);
  for (std::string token; stream >> token;) tokens.push_back(token);
  return tokens;
}

bool is_number(const std::string& token) {
  try {
    parse_number(token, "");
    return true;
  } catch (const std::invalid_argument&) {
    return false;
  }
}

std::size_t column_index(const std::vector<std::string>& names, const std::string& wanted, const std::string& where) {
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (names[i] == wanted) return i;
  }
  std::string listed;
  for (const auto& name : names) {
    if (!listed.empty()) listed += ", ";
    listed += name;
  }
  throw std::invalid_argument(where + ": no '" + wanted + "' column (columns: " + listed + ")");
}

std::string stem(const std::string& path) { return std::filesystem::path(path).stem().string(); }

// The rows below a header, each split by `row_cells`, as x and y.
template <typename SplitRow>
void read_table(const std::vector<std::string>& lines, std::size_t header_line, const std::vector<std::string>& names,
                const std::string& path, SplitRow row_cells, DataSet& data) {
  const std::size_t x_column = column_index(names, "x", path + " line " + std::to_string(header_line + 1));
  const std::size_t y_column = column_index(names, "y", path + " line " + std::to_string(header_line + 1));
  std::vector<double> xs, ys;
  for (std::size_t i = header_line + 1; i < lines.size(); ++i) {
    if (lines[i].find_first_not_of(" \t") == std::string::npos) continue;
    const std::vector<std::string> cells = row_cells(lines[i]);
    const std::string where = path + " line " + std::to_string(i + 1);
    if (cells.size() != names.size()) {
      throw std::invalid_argument(where + ": " + std::to_string(cells.size()) + " values, but the header names " +
                                  std::to_string(names.size()) + " columns");
    }
    xs.push_back(parse_number(cells[x_column], where + ", column x"));
    ys.push_back(parse_number(cells[y_column], where + ", column y"));
  }
  if (xs.empty()) throw std::invalid_argument(path + ": no data rows below the header");
  data.x = Eigen::Map<const Eigen::VectorXd>(xs.data(), static_cast<Eigen::Index>(xs.size()));
  data.y = Eigen::Map<const Eigen::VectorXd>(ys.data(), static_cast<Eigen::Index>(ys.size()));
}

}  // namespace

double parse_number(const std::string& token, const std::string& where) {
  // from_chars reads NIST's "760." and ".11019"; it rejects a leading '+', so skip one.
  const char* first = token.data();
  const char* last = token.data() + token.size();
  if (first != last && *first == '+') ++first;
  double value = 0.0;
  const auto [stop, error] = std::from_chars(first, last, value);
  if (token.empty() || error != std::errc() || stop != last) {
    throw std::invalid_argument(where + ": '" + token + "' is not a number");
  }
  if (!std::isfinite(value)) throw std::invalid_argument(where + ": '" + token + "' is not a finite number");
  return value;
}

DataSet read_csv_data(const std::string& path) {
  const std::vector<std::string> lines = read_lines(path);
  std::size_t header = 0;
  while (header < lines.size() && lines[header].find_first_not_of(" \t") == std::string::npos) ++header;
  if (header == lines.size()) throw std::invalid_argument(path + ": the file is empty");
  DataSet data{stem(path), {}, {}, std::nullopt};
  read_table(lines, header, split(lines[header], ','), path, [](const std::string& line) { return split(line, ','); },
             data);
  return data;
}

DataSet read_nist_data(const std::string& path) {
  const std::vector<std::string> lines = read_lines(path);
  CertifiedValues certified;
  bool polynomial_model = true;
  std::optional<std::size_t> table_header;
  for (std::size_t i = 0; i < lines.size() && !table_header; ++i) {
    const std::vector<std::string> tokens = words(lines[i]);
    if (tokens.empty()) continue;
    const std::string where = path + " line " + std::to_string(i + 1);
    // "B3   value   sd": a certified parameter, in order B0, B1, ...
    const bool parameter_line = tokens.size() == 3 && tokens[0].size() > 1 && tokens[0][0] == 'B' &&
                                tokens[0].find_first_not_of("0123456789", 1) == std::string::npos;
    if (parameter_line) {
      // A model without B0 (NIST's NoInt sets) is not a polynomial with an intercept.
      polynomial_model = polynomial_model && tokens[0].substr(1) == std::to_string(certified.parameters.size());
      certified.parameters.push_back(parse_number(tokens[1], where));
      certified.standard_deviations.push_back(parse_number(tokens[2], where));
    } else if (tokens.size() == 3 && tokens[0] == "Standard" && tokens[1] == "Deviation" && is_number(tokens[2])) {
      certified.residual_sd = parse_number(tokens[2], where);
    } else if (tokens.size() == 2 && tokens[0] == "R-Squared") {
      certified.r_squared = parse_number(tokens[1], where);
    } else if (tokens[0] == "Data:" && tokens.size() >= 3) {
      // "Data:  y  x": the table header (the earlier "Data:  1 Response Variable" line starts with a number).
      bool all_names = true;
      for (std::size_t t = 1; t < tokens.size(); ++t) all_names = all_names && !is_number(tokens[t]);
      if (all_names) table_header = i;
    }
  }
  if (!table_header) throw std::invalid_argument(path + ": no 'Data:  y  x' table header; is this a NIST StRD file?");
  std::vector<std::string> names = words(lines[*table_header]);
  names.erase(names.begin());  // "Data:"
  DataSet data{stem(path), {}, {}, std::nullopt};
  read_table(lines, *table_header, names, path, words, data);
  // Certified values belong to the model y = B0 + B1 x + ... only; others are not attached.
  if (!certified.parameters.empty() && polynomial_model) data.certified = certified;
  return data;
}

DataSet read_data_file(const std::string& path) {
  return std::filesystem::path(path).extension() == ".dat" ? read_nist_data(path) : read_csv_data(path);
}

}  // namespace numlab::fitting
