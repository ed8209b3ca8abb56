#include <catch2/catch.hpp>

#include "numlab/linalg/matrix_file.hpp"

using namespace numlab::linalg;
using Catch::Matchers::Contains;

TEST_CASE("Matrix files: whitespace or commas, comments, blank lines", "[matrix-file]") {
  const Eigen::MatrixXd M = parse_matrix("# a 2x3 matrix\n1, 2, 3\n\n  4 5\t6.5e-1  # trailing comment\n", "text");
  REQUIRE(M.rows() == 2);
  REQUIRE(M.cols() == 3);
  CHECK(M(0, 2) == 3.0);
  CHECK(M(1, 2) == 0.65);
  CHECK(parse_matrix("+1 -2", "text")(0, 0) == 1.0);
}

TEST_CASE("Malformed matrix files are refused with the file, line and token", "[matrix-file][bad-input]") {
  CHECK_THROWS_WITH(parse_matrix("1 2\n3 x\n", "m.txt"), Contains("m.txt:2") && Contains("'x' is not a number"));
  CHECK_THROWS_WITH(parse_matrix("1 2\n3\n", "m.txt"), Contains("m.txt:2") && Contains("1 numbers, earlier rows have 2"));
  CHECK_THROWS_WITH(parse_matrix("# nothing\n\n", "m.txt"), Contains("no numbers"));
  CHECK_THROWS_WITH(parse_matrix("1 nan\n", "m.txt"), Contains("not a finite number"));
  CHECK_THROWS_WITH(parse_matrix("1 1e999\n", "m.txt"), Contains("out of range"));
  CHECK_THROWS_WITH(parse_matrix("1 2.5.3\n", "m.txt"), Contains("'2.5.3'"));
  CHECK_THROWS_WITH(read_matrix_file("/nonexistent/matrix.txt"), Contains("cannot open"));
}
