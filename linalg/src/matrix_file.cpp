#include "numlab/linalg/matrix_file.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "numlab/printable_text.hpp"

namespace numlab::linalg {

namespace {

constexpr std::string_view separators = " \t\r\v\f,";
constexpr std::string_view blanks = " \t\r\v\f";
// A file descriptor closed when it goes out of scope.
struct OpenFile {
  explicit OpenFile(int fd) : descriptor(fd) {}
  OpenFile(const OpenFile&) = delete;
  OpenFile& operator=(const OpenFile&) = delete;
  ~OpenFile() {
    if (descriptor >= 0) ::close(descriptor);
  }
  int descriptor;
};

// How long a FIFO may stay silent before numlab says so (a shell's <(command) is a FIFO).
constexpr int fifo_wait_ms = 10000;

// "16 MiB" for whole mebibytes, else the byte count.
std::string size_text(std::size_t bytes) {
  constexpr std::size_t mebibyte = std::size_t{1} << 20;
  return bytes % mebibyte == 0 ? std::to_string(bytes / mebibyte) + " MiB" : std::to_string(bytes) + " bytes";
}

[[noreturn]] void fail(const std::string& source, int line, const std::string& what) {
  throw std::invalid_argument(printable(source) + ":" + std::to_string(line) + ": " + what);
}

[[noreturn]] void fail_at(const std::string& source, int line, std::size_t column, const std::string& what) {
  throw std::invalid_argument(printable(source) + ":" + std::to_string(line) + ":" + std::to_string(column) + ": " + what);
}

// Splits one line (comment already removed) on whitespace and commas, and appends each number to
// `values`; returns how many. A comma separates two numbers: one with no number before or after it
// marks an empty field.
std::size_t parse_row(std::string_view line, const std::string& source, int line_number, std::vector<double>& values) {
  std::size_t count = 0;
  bool number_since_comma = false;
  std::size_t last_comma = std::string_view::npos;
  std::size_t position = line.find_first_not_of(blanks);
  while (position != std::string_view::npos) {
    if (line[position] == ',') {
      if (!number_since_comma) {
        fail_at(source, line_number, position + 1,
                last_comma == std::string_view::npos ? "empty field: a comma with no number before it"
                                                     : "empty field between two commas");
      }
      number_since_comma = false;
      last_comma = position;
      position = line.find_first_not_of(blanks, position + 1);
      continue;
    }
    std::size_t end = line.find_first_of(separators, position);
    if (end == std::string_view::npos) end = line.size();
    const std::string_view token = line.substr(position, end - position);
    double value = 0.0;
    const NumberTokenError error = parse_number_token(token, value);
    if (error != NumberTokenError::none) fail(source, line_number, number_token_problem(token, error));
    values.push_back(value);
    ++count;
    number_since_comma = true;
    position = line.find_first_not_of(blanks, end);
  }
  if (last_comma != std::string_view::npos && !number_since_comma) {
    fail_at(source, line_number, last_comma + 1, "empty field: a comma with no number after it");
  }
  return count;
}

}  // namespace

std::string read_text_file(const std::string& path, std::size_t max_bytes) {
  const std::string name = printable(path);
  // 1. Open without blocking: opening a FIFO for reading would otherwise wait for a writer forever.
  const OpenFile file{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC)};
  const int fd = file.descriptor;
  if (fd < 0) throw std::invalid_argument(name + ": cannot open the file (missing or unreadable)");
  struct stat info {};
  if (::fstat(fd, &info) != 0) throw std::invalid_argument(name + ": cannot read the file");
  if (S_ISDIR(info.st_mode)) throw std::invalid_argument(name + ": is a directory, not a file");
  // 2. A pipe must bring data (or its end) within fifo_wait_ms; then read as from any file.
  if (S_ISFIFO(info.st_mode)) {
    pollfd waiting{fd, POLLIN, 0};
    if (::poll(&waiting, 1, fifo_wait_ms) == 0) {
      throw std::invalid_argument(name + ": a pipe with nothing written to it within " +
                                  std::to_string(fifo_wait_ms / 1000) + " s");
    }
  }
  ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
  // 3. Read in chunks, never more than max_bytes + 1 bytes in all (a device may never end).
  std::string text;
  std::array<char, 1 << 16> chunk{};
  while (text.size() <= max_bytes) {
    const std::size_t wanted = std::min(chunk.size(), max_bytes + 1 - text.size());
    const ssize_t got = ::read(fd, chunk.data(), wanted);
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) throw std::invalid_argument(name + ": cannot read the file");
    if (got == 0) break;
    text.append(chunk.data(), static_cast<std::size_t>(got));
  }
  // 4. One byte past the limit means the file is too long to be an input file.
  if (text.size() > max_bytes) {
    throw std::invalid_argument(name + ": longer than the " + size_text(max_bytes) + " limit for input files");
  }
  return text;
}

std::string_view without_byte_order_mark(std::string_view text) {
  constexpr std::string_view mark = "\xEF\xBB\xBF";
  return text.starts_with(mark) ? text.substr(mark.size()) : text;
}

NumberTokenError parse_number_token(std::string_view token, double& value) {
  if (token.empty()) return NumberTokenError::empty;
  // from_chars reads "760." and ".11019" but rejects a leading '+', so skip one.
  const char* first = token.data() + (token.front() == '+' ? 1 : 0);
  const char* last = token.data() + token.size();
  const auto [stop, error] = std::from_chars(first, last, value);
  if (error == std::errc::result_out_of_range && stop == last) return NumberTokenError::out_of_range;
  if (error != std::errc() || stop != last) return NumberTokenError::not_a_number;
  return std::isfinite(value) ? NumberTokenError::none : NumberTokenError::not_finite;
}

std::string quoted_token(std::string_view token) {
  constexpr std::size_t shown = 40;
  std::string quoted(1, '\'');
  quoted += printable(token.substr(0, shown));
  quoted += token.size() > shown ? "...'" : "'";
  return quoted;
}

std::string number_token_problem(std::string_view token, NumberTokenError error) {
  switch (error) {
    case NumberTokenError::none: return "";
    case NumberTokenError::empty: return "empty value where a number belongs";
    case NumberTokenError::out_of_range: return quoted_token(token) + " is out of range";
    case NumberTokenError::not_finite: return quoted_token(token) + " is not a finite number";
    case NumberTokenError::not_a_number: break;
  }
  return quoted_token(token) + " is not a number";
}

Eigen::MatrixXd parse_matrix(std::string_view text, const std::string& source) {
  text = without_byte_order_mark(text);
  std::vector<double> values;  // row after row
  std::size_t rows = 0, columns = 0;
  int line_number = 0;
  for (std::size_t begin = 0; begin < text.size();) {
    // 1. One line, without its comment.
    ++line_number;
    const std::size_t end = std::min(text.find('\n', begin), text.size());
    const std::string_view line = text.substr(begin, end - begin);
    begin = end + 1;
    const std::size_t count = parse_row(line.substr(0, line.find('#')), source, line_number, values);
    // 2. Blank lines are skipped; every other row has the first row's length.
    if (count == 0) continue;
    if (rows > 0 && count != columns) {
      fail(source, line_number,
           "row has " + std::to_string(count) + " numbers, earlier rows have " + std::to_string(columns));
    }
    columns = count;
    ++rows;
  }
  if (rows == 0) throw std::invalid_argument(printable(source) + ": no numbers found");
  using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  return Eigen::Map<const RowMajor>(values.data(), static_cast<Eigen::Index>(rows), static_cast<Eigen::Index>(columns));
}

Eigen::MatrixXd read_matrix_file(const std::string& path) { return parse_matrix(read_text_file(path), path); }

Eigen::VectorXd read_vector_file(const std::string& path) {
  const Eigen::MatrixXd values = read_matrix_file(path);
  if (values.cols() != 1 && values.rows() != 1) {
    throw std::invalid_argument(printable(path) + ": a vector must be one row or one column, got " +
                                std::to_string(values.rows()) + "x" + std::to_string(values.cols()));
  }
  return Eigen::Map<const Eigen::VectorXd>(values.data(), values.size());
}

}  // namespace numlab::linalg
