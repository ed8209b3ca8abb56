#pragma once
// Reading matrices and vectors from text files:
// rows of numbers separated by whitespace or commas; '#' starts a comment; blank lines are skipped.

#include <Eigen/Core>
#include <string>

namespace numlab::linalg {

// Throws std::invalid_argument naming the file, line and token for: an unreadable file, a token
// that is not a number, a non-finite number, rows of different lengths, or a file with no numbers.
Eigen::MatrixXd read_matrix_file(const std::string& path);

// Parses the same format from a string; `source` names it in error messages.
Eigen::MatrixXd parse_matrix(const std::string& text, const std::string& source);

// A vector file: one column, or one row.
Eigen::VectorXd read_vector_file(const std::string& path);

}  // namespace numlab::linalg
