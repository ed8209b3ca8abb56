#include "numlab/fitting/data_set.hpp"

#include <algorithm>
#include <charconv>
#include <filesystem>
#include <stdexcept>
#include <string_view>
#include <tuple>

#include "numlab/linalg/matrix_file.hpp"
#include "numlab/printable_text.hpp"

namespace numlab::fitting {

namespace {

using linalg::quoted_token;
constexpr std::string_view blanks = " \t\r\v\f";

std::string_view trimmed(std::string_view text) {
  const std::size_t first = text.find_first_not_of(blanks);
  if (first == std::string_view::npos) return {};
  return text.substr(first, text.find_last_not_of(blanks) - first + 1);
}

// The lines of a text one at a time (a byte-order mark skipped, "\r\n" read as "\n"), numbered from 1.
class Lines {
 public:
  explicit Lines(std::string_view text) : text_(linalg::without_byte_order_mark(text)) {}
  bool next(std::string_view& line) {
    if (position_ >= text_.size()) return false;
    const std::size_t end = std::min(text_.find('\n', position_), text_.size());
    line = text_.substr(position_, end - position_);
    if (line.ends_with('\r')) line.remove_suffix(1);
    position_ = end + 1;
    ++number_;
    return true;
  }
  std::size_t number() const { return number_; }

 private:
  std::string_view text_;
  std::size_t position_ = 0;
  std::size_t number_ = 0;
};

// The cells of one line, one at a time: comma-separated and trimmed (CSV), or blank-separated words (NIST).
class Cells {
 public:
  Cells(std::string_view line, bool commas) : line_(line), commas_(commas) {}
  bool next(std::string_view& cell) {
    if (done_) return false;
    if (commas_) {
      const std::size_t end = std::min(line_.find(',', position_), line_.size());
      cell = trimmed(line_.substr(position_, end - position_));
      done_ = end == line_.size();
      position_ = end + 1;
      return true;
    }
    const std::size_t begin = line_.find_first_not_of(blanks, position_);
    if (begin == std::string_view::npos) {
      done_ = true;
      return false;
    }
    const std::size_t end = std::min(line_.find_first_of(blanks, begin), line_.size());
    cell = line_.substr(begin, end - begin);
    position_ = end;
    return true;
  }

 private:
  std::string_view line_;
  bool commas_;
  std::size_t position_ = 0;
  bool done_ = false;
};

bool is_blank(std::string_view line) { return line.find_first_not_of(blanks) == std::string_view::npos; }

bool is_number(std::string_view token) {
  double value = 0.0;
  return linalg::parse_number_token(token, value) == linalg::NumberTokenError::none;
}

// Where the x and y columns are among a header's names.
struct Columns {
  std::size_t count = 0;
  std::size_t x = 0, y = 0;
};

Columns find_columns(Cells names, const std::string& where) {
  constexpr std::size_t listed_at_most = 8;
  Columns columns;
  bool have_x = false, have_y = false;
  std::string listed;
  for (std::string_view name; names.next(name); ++columns.count) {
    if (columns.count < listed_at_most) listed += (listed.empty() ? "" : ", ") + quoted_token(name);
    if (columns.count == listed_at_most) listed += ", ...";
    for (auto [wanted, have, index] : {std::tuple{"x", &have_x, &columns.x}, std::tuple{"y", &have_y, &columns.y}}) {
      if (name != wanted) continue;
      if (*have) throw std::invalid_argument(where + ": two columns are named '" + wanted + "'");
      *have = true;
      *index = columns.count;
    }
  }
  for (auto [wanted, have] : {std::pair{"x", have_x}, std::pair{"y", have_y}}) {
    if (!have) throw std::invalid_argument(where + ": no '" + wanted + "' column (columns: " + listed + ")");
  }
  return columns;
}

// The rows below a header (blank lines skipped), as x and y.
void read_table(Lines& lines, const Columns& columns, bool commas, const std::string& source, DataSet& data) {
  std::vector<double> xs, ys;
  for (std::string_view line; lines.next(line);) {
    if (is_blank(line)) continue;
    const std::string where = source + " line " + std::to_string(lines.number());
    std::string_view x, y;
    std::size_t count = 0;
    Cells cells(line, commas);
    for (std::string_view cell; cells.next(cell); ++count) {
      if (count == columns.x) x = cell;
      if (count == columns.y) y = cell;
    }
    if (count != columns.count) {
      throw std::invalid_argument(where + ": " + std::to_string(count) + " values, but the header names " +
                                  std::to_string(columns.count) + " columns");
    }
    xs.push_back(parse_number(std::string(x), where + ", column x"));
    ys.push_back(parse_number(std::string(y), where + ", column y"));
  }
  if (xs.empty()) throw std::invalid_argument(source + ": no data rows below the header");
  data.x = Eigen::Map<const Eigen::VectorXd>(xs.data(), static_cast<Eigen::Index>(xs.size()));
  data.y = Eigen::Map<const Eigen::VectorXd>(ys.data(), static_cast<Eigen::Index>(ys.size()));
}

// The first three words of a line, and how many words it has.
std::size_t first_words(std::string_view line, std::string_view (&words)[3]) {
  std::size_t count = 0;
  Cells cells(line, false);
  for (std::string_view word; cells.next(word); ++count) {
    if (count < std::size(words)) words[count] = word;
  }
  return count;
}

// "B3": a certified parameter's name; its index, or -1.
long parameter_index(std::string_view word) {
  long index = -1;
  if (word.size() < 2 || word.size() > 4 || word[0] != 'B') return -1;
  const auto [stop, error] = std::from_chars(word.data() + 1, word.data() + word.size(), index);
  return error == std::errc() && stop == word.data() + word.size() && word[1] != '-' ? index : -1;
}

std::string stem(const std::string& path) { return std::filesystem::path(path).stem().string(); }

}  // namespace

double parse_number(const std::string& token, const std::string& where) {
  double value = 0.0;
  const linalg::NumberTokenError error = linalg::parse_number_token(token, value);
  if (error != linalg::NumberTokenError::none) {
    throw std::invalid_argument(where + ": " + linalg::number_token_problem(token, error));
  }
  return value;
}

DataSet parse_csv_data(std::string_view text, const std::string& source) {
  const std::string name = printable(source);
  Lines lines(text);
  std::string_view header;
  while (lines.next(header) && is_blank(header)) {
  }
  if (is_blank(header)) throw std::invalid_argument(name + ": the file is empty");
  DataSet data{stem(source), {}, {}, std::nullopt};
  const Columns columns = find_columns(Cells(header, true), name + " line " + std::to_string(lines.number()));
  read_table(lines, columns, true, name, data);
  return data;
}

DataSet parse_nist_data(std::string_view text, const std::string& source) {
  const std::string name = printable(source);
  Lines lines(text);
  CertifiedValues certified;
  bool polynomial_model = true;
  std::optional<std::size_t> observations;
  std::string_view line;
  bool table_header = false;
  // 1. The header: the number of observations, the certified values, up to the "Data:  y  x" line.
  while (!table_header && lines.next(line)) {
    std::string_view words[3];
    const std::size_t count = first_words(line, words);
    const std::string where = name + " line " + std::to_string(lines.number());
    if (count == 3 && parameter_index(words[0]) >= 0) {
      // "B3   value   sd": a certified parameter, in order B0, B1, ...; a model without B0 (NIST's
      // NoInt sets) is not a polynomial with an intercept.
      polynomial_model = polynomial_model && parameter_index(words[0]) == static_cast<long>(certified.parameters.size());
      certified.parameters.push_back(parse_number(std::string(words[1]), where));
      certified.standard_deviations.push_back(parse_number(std::string(words[2]), where));
    } else if (count == 3 && words[0] == "Standard" && words[1] == "Deviation" && is_number(words[2])) {
      certified.residual_sd = parse_number(std::string(words[2]), where);
    } else if (count == 2 && words[0] == "R-Squared") {
      certified.r_squared = parse_number(std::string(words[1]), where);
    } else if (count == 2 && words[1] == "Observations" && !observations) {
      // "36 Observations": how many rows the data table must have.
      std::size_t rows = 0;
      const auto [stop, error] = std::from_chars(words[0].data(), words[0].data() + words[0].size(), rows);
      if (error != std::errc() || stop != words[0].data() + words[0].size()) {
        throw std::invalid_argument(where + ": " + quoted_token(words[0]) + " is not a number of observations");
      }
      observations = rows;
    } else if (count >= 3 && words[0] == "Data:") {
      // "Data:  y  x": the table header (the earlier "Data:  1 Response Variable" line starts with a number).
      Cells names(line, false);
      bool all_names = true;
      for (std::string_view word; names.next(word);) all_names = all_names && !is_number(word);
      table_header = all_names;
    }
  }
  if (!table_header) throw std::invalid_argument(name + ": no 'Data:  y  x' table header; is this a NIST StRD file?");
  if (!observations) {
    throw std::invalid_argument(name + ": no 'N Observations' line above the data; is this a NIST StRD file?");
  }
  // 2. The table, whose row count must be the header's.
  const std::size_t header_line = lines.number();
  Cells names(line, false);
  std::string_view data_word;
  names.next(data_word);  // "Data:"
  const Columns columns = find_columns(names, name + " line " + std::to_string(header_line));
  DataSet data{stem(source), {}, {}, std::nullopt};
  read_table(lines, columns, false, name, data);
  if (static_cast<std::size_t>(data.x.size()) != *observations) {
    throw std::invalid_argument(name + ": the header says " + std::to_string(*observations) +
                                " observations, but the data table below line " + std::to_string(header_line) +
                                " has " + std::to_string(data.x.size()) + " rows");
  }
  // 3. Certified values belong to the model y = B0 + B1 x + ... only; others are not attached.
  if (!certified.parameters.empty() && polynomial_model) data.certified = certified;
  return data;
}

DataSet read_csv_data(const std::string& path) { return parse_csv_data(linalg::read_text_file(path), path); }

DataSet read_nist_data(const std::string& path) { return parse_nist_data(linalg::read_text_file(path), path); }

DataSet read_data_file(const std::string& path) {
  return std::filesystem::path(path).extension() == ".dat" ? read_nist_data(path) : read_csv_data(path);
}

}  // namespace numlab::fitting
