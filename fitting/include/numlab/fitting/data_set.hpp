#pragma once
// Data for a fit: x and y read from a CSV file with a header, or from a NIST StRD `.dat` file
// (which also carries NIST's certified parameters and statistics).

#include <Eigen/Core>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace numlab::fitting {

// NIST's certified results for a polynomial model y = B0 + B1 x + ... + BD x^D.
struct CertifiedValues {
  std::vector<double> parameters;  // B0 ... BD
  std::vector<double> standard_deviations;
  double residual_sd = 0.0;
  double r_squared = 0.0;
};

struct DataSet {
  std::string name;  // the file name without folder and extension
  Eigen::VectorXd x;
  Eigen::VectorXd y;
  std::optional<CertifiedValues> certified;  // NIST `.dat` files only
};

// Files are read whole, up to linalg::max_input_file_bytes (16 MiB); a UTF-8 byte-order mark at the
// start is skipped and "\r\n" line ends are read as "\n". The parse_* functions read the same
// formats from text (`source` names it in messages and gives DataSet::name).

// A CSV file whose header names an `x` and a `y` column (any order; other columns are ignored).
// Throws std::invalid_argument naming the file, line and value for: a missing or unreadable file,
// a directory, a file over the size limit, an empty file, a missing or twice-named x or y column, a
// row of the wrong length, a value that is empty or not a finite number, or no data rows.
DataSet read_csv_data(const std::string& path);
DataSet parse_csv_data(std::string_view text, const std::string& source);

// A NIST StRD file: the "N Observations" line, the certified parameter lines ("B0  value  sd"), the
// residual standard deviation, R-squared, and the "Data:  y  x" table, which must have N rows.
// Numbers in NIST's notation are accepted ("760.", ".11019", "0.1E-01"). Throws
// std::invalid_argument as read_csv_data does, and when the header's count and the table's differ.
DataSet read_nist_data(const std::string& path);
DataSet parse_nist_data(std::string_view text, const std::string& source);

// A file ending in `.dat` is read as NIST StRD, anything else as CSV.
DataSet read_data_file(const std::string& path);

// One number: the whole token must parse and be finite. `where` names the place in messages
// (the token is quoted there with numlab::printable, at most 40 bytes shown).
double parse_number(const std::string& token, const std::string& where);

}  // namespace numlab::fitting
