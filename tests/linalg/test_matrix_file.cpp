#include <catch2/catch.hpp>

#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <thread>

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

namespace {

// A fresh, empty folder for one test.
std::filesystem::path scratch_folder(const std::string& name) {
  const auto folder = std::filesystem::temp_directory_path() / ("numlab-test-matrix-file-" + name);
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  return folder;
}

void write_bytes(const std::filesystem::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

}  // namespace

TEST_CASE("An empty field between commas is refused with its line and column", "[matrix-file][bad-input]") {
  CHECK_THROWS_WITH(parse_matrix("1,2\n1,,2\n", "m.txt"), Contains("m.txt:2:3: empty field between two commas"));
  CHECK_THROWS_WITH(parse_matrix(" ,1\n", "m.txt"), Contains("m.txt:1:2: empty field: a comma with no number before it"));
  CHECK_THROWS_WITH(parse_matrix("1, 2 ,\n", "m.txt"), Contains("m.txt:1:6: empty field: a comma with no number after it"));
  // Commas with blanks around them still separate two numbers.
  const Eigen::MatrixXd M = parse_matrix("1 , 2,3\n4,5 ,\t6 # 7,,\n", "m.txt");
  CHECK(M == (Eigen::MatrixXd(2, 3) << 1, 2, 3, 4, 5, 6).finished());
}

TEST_CASE("A UTF-8 byte-order mark at the start is skipped, anywhere else it is not a number", "[matrix-file]") {
  const Eigen::MatrixXd M = parse_matrix("\xEF\xBB\xBF-1.5 2\n3 4\n", "bom.txt");
  CHECK(M == (Eigen::MatrixXd(2, 2) << -1.5, 2, 3, 4).finished());
  CHECK_THROWS_WITH(parse_matrix("1 2\n\xEF\xBB\xBF" "3 4\n", "bom.txt"), Contains("bom.txt:2: '\\xef\\xbb\\xbf3'"));
}

TEST_CASE("Bytes from a file are echoed escaped, on one line, at most 40 of them", "[matrix-file][bad-input]") {
  try {
    parse_matrix("1 \x1b]0;title\x07\r\n", "m.txt");
    FAIL("no exception");
  } catch (const std::invalid_argument& error) {
    const std::string message = error.what();
    CHECK(message == "m.txt:1: '\\x1b]0;title\\x07' is not a number");
  }
  const std::string long_token = "7" + std::string(99, 'x');
  CHECK_THROWS_WITH(parse_matrix(long_token, "m.txt"),
                    "m.txt:1: '7" + std::string(39, 'x') + "...' is not a number");
  // A file name with control bytes is escaped too.
  CHECK_THROWS_WITH(parse_matrix("x", "a\nb.txt"), "a\\x0ab.txt:1: 'x' is not a number");
}

TEST_CASE("Files are read up to a byte cap, in chunks, so devices and FIFOs end", "[matrix-file][bad-input]") {
  const auto folder = scratch_folder("cap");
  // The cap is exact: max_bytes bytes are read, one more is refused.
  write_bytes(folder / "ten.txt", "1 2 3 4 5\n");
  CHECK(read_text_file((folder / "ten.txt").string(), 10) == "1 2 3 4 5\n");
  CHECK_THROWS_WITH(read_text_file((folder / "ten.txt").string(), 9), Contains("longer than the 9 bytes limit"));
  // A character device that never ends.
  CHECK_THROWS_WITH(read_matrix_file("/dev/zero"), "/dev/zero: longer than the 16 MiB limit for input files");
  CHECK_THROWS_WITH(read_vector_file("/dev/zero"), Contains("16 MiB"));
  // A FIFO: read until its writer closes it.
  const auto fifo = folder / "fifo";
  REQUIRE(mkfifo(fifo.c_str(), 0600) == 0);
  std::jthread writer([&] { write_bytes(fifo, "1 2\n3 4\n"); });
  const Eigen::MatrixXd M = read_matrix_file(fifo.string());
  writer.join();
  CHECK(M == (Eigen::MatrixXd(2, 2) << 1, 2, 3, 4).finished());
  std::filesystem::remove_all(folder);
}

TEST_CASE("A directory given as a matrix file is named as one", "[matrix-file][bad-input]") {
  const auto folder = scratch_folder("directory");
  CHECK_THROWS_WITH(read_matrix_file(folder.string()), folder.string() + ": is a directory, not a file");
  std::filesystem::remove_all(folder);
}

TEST_CASE("One number token: what is wrong with it", "[matrix-file]") {
  double value = 0.0;
  CHECK(parse_number_token("+2.5e-3", value) == NumberTokenError::none);
  CHECK(value == 2.5e-3);
  CHECK(parse_number_token("", value) == NumberTokenError::empty);
  CHECK(parse_number_token("1e400", value) == NumberTokenError::out_of_range);
  CHECK(parse_number_token("-inf", value) == NumberTokenError::not_finite);
  CHECK(parse_number_token("1e400x", value) == NumberTokenError::not_a_number);
  CHECK(parse_number_token("++1", value) == NumberTokenError::not_a_number);
  CHECK(parse_number_token("0x10", value) == NumberTokenError::not_a_number);
}
