// libFuzzer target: numlab::linalg::parse_matrix, the reader of --matrix and --rhs files.
// Promise kept on success: at least one row and one column, every entry finite.

#include "fuzz_target.hpp"
#include "numlab/linalg/matrix_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace numlab;
  return fuzz::run_parser([&] {
    const Eigen::MatrixXd matrix = linalg::parse_matrix(fuzz::as_text(data, size), "fuzz.txt");
    fuzz::require(matrix.rows() > 0 && matrix.cols() > 0, "an empty matrix was returned");
    fuzz::require(matrix.allFinite(), "a non-finite entry was returned");
  });
}
