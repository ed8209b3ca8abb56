#pragma once
// Data for a fit: x and y read from a CSV file with a header, or from a NIST StRD `.dat` file
// (which also carries NIST's certified parameters and statistics).

#include <Eigen/Core>
#include <optional>
#include <string>
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

// A CSV file whose header names an `x` and a `y` column (any order; other columns are ignored).
// Throws std::invalid_argument naming the file, line and value for: a missing file, a missing
// column, a row of the wrong length, a value that is not a finite number, or no data rows.
DataSet read_csv_data(const std::string& path);

// A NIST StRD file: the certified parameter lines ("B0  value  sd"), the residual standard
// deviation, R-squared, and the "Data:  y  x" table. Numbers in NIST's notation are accepted
// ("760.", ".11019", "0.1E-01"). Throws std::invalid_argument as read_csv_data does.
DataSet read_nist_data(const std::string& path);

// A file ending in `.dat` is read as NIST StRD, anything else as CSV.
DataSet read_data_file(const std::string& path);

// One number: the whole token must parse and be finite. `where` names the place in messages.
double parse_number(const std::string& token, const std::string& where);

}  // namespace numlab::fitting
