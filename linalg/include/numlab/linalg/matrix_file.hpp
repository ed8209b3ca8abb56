#pragma once
// Reading matrices and vectors from text files:
// rows of numbers separated by whitespace or commas; '#' starts a comment; blank lines are skipped.
// Also the pieces every numlab input reader shares: a file read with a byte cap, one number token,
// and a token quoted safely for an error message.

#include <Eigen/Core>
#include <cstddef>
#include <string>
#include <string_view>

namespace numlab::linalg {

// The largest input file numlab reads (matrix, vector and data files): 16 MiB.
inline constexpr std::size_t max_input_file_bytes = std::size_t{16} << 20;

// The whole file, read in chunks so that character devices and FIFOs work too. Throws
// std::invalid_argument naming the file for: a directory, a file that cannot be opened or read,
// a FIFO with nothing written to it within 10 s, and a file longer than max_bytes (reading stops
// at max_bytes + 1).
std::string read_text_file(const std::string& path, std::size_t max_bytes = max_input_file_bytes);

// The text without a leading UTF-8 byte-order mark (EF BB BF), if it has one.
std::string_view without_byte_order_mark(std::string_view text);

// One number token: the whole token must parse (a leading '+' is allowed) and be finite.
enum class NumberTokenError { none, empty, not_a_number, out_of_range, not_finite };
NumberTokenError parse_number_token(std::string_view token, double& value);

// "'token'" for a message: control and ill-formed bytes escaped by numlab::printable, at most
// 40 bytes of the token shown, then "...".
std::string quoted_token(std::string_view token);

// What is wrong with a token, for a message, e.g. "'1e999' is out of range" ("" for none).
std::string number_token_problem(std::string_view token, NumberTokenError error);

// Throws std::invalid_argument naming the file, line and token for: an unreadable file, a token
// that is not a number, a non-finite number, an empty field between commas (line and column),
// rows of different lengths, or a file with no numbers. A byte-order mark at the start is skipped.
Eigen::MatrixXd read_matrix_file(const std::string& path);

// Parses the same format from a string; `source` names it in error messages.
Eigen::MatrixXd parse_matrix(std::string_view text, const std::string& source);

// A vector file: one column, or one row.
Eigen::VectorXd read_vector_file(const std::string& path);

}  // namespace numlab::linalg
