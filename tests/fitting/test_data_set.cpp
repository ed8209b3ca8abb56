// Reading data sets under hostile input: CSV edge cases, NIST .dat files whose table does not match
// their header, and files that are not files at all. Each refusal names the file, line and problem.

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "numlab/fitting/data_set.hpp"

using namespace numlab::fitting;
using Catch::Matchers::Contains;

namespace {

std::string nist_text(const std::string& name) {
  std::ifstream file(std::string(NUMLAB_NIST_DIR) + "/" + name + ".dat", std::ios::binary);
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

// The text up to and including the first `rows` rows below the "Data:  y  x" header.
std::string with_first_rows(const std::string& text, int rows) {
  std::size_t end = text.find("\nData:       y");
  for (int i = 0; i <= rows; ++i) end = text.find('\n', end + 1);
  return text.substr(0, end + 1);
}

}  // namespace

TEST_CASE("CSV: columns in any order, extra columns, blank lines, CRLF and a byte-order mark", "[data-set]") {
  const DataSet data = parse_csv_data("\xEF\xBB\xBF" "note, y ,x\r\n\r\na,2.5,1\r\nb,-3,+2\r\n", "dir/points.csv");
  CHECK(data.name == "points");
  CHECK(data.x == Eigen::Vector2d(1.0, 2.0));
  CHECK(data.y == Eigen::Vector2d(2.5, -3.0));
  CHECK_FALSE(data.certified);
}

TEST_CASE("CSV edge cases are refused with file, line and problem", "[data-set][bad-input]") {
  CHECK_THROWS_WITH(parse_csv_data("", "d.csv"), "d.csv: the file is empty");
  CHECK_THROWS_WITH(parse_csv_data("\xEF\xBB\xBF \r\n\n", "d.csv"), "d.csv: the file is empty");
  CHECK_THROWS_WITH(parse_csv_data("x,y\n\n", "d.csv"), "d.csv: no data rows below the header");
  CHECK_THROWS_WITH(parse_csv_data("x,z\n1,2\n", "d.csv"), "d.csv line 1: no 'y' column (columns: 'x', 'z')");
  CHECK_THROWS_WITH(parse_csv_data("a,y\n1,2\n", "d.csv"), Contains("no 'x' column"));
  CHECK_THROWS_WITH(parse_csv_data("x,y,x\n1,2,3\n", "d.csv"), "d.csv line 1: two columns are named 'x'");
  CHECK_THROWS_WITH(parse_csv_data("x,y\n1,2\n3\n", "d.csv"), "d.csv line 3: 1 values, but the header names 2 columns");
  CHECK_THROWS_WITH(parse_csv_data("x,y\n1,2,\n", "d.csv"), Contains("line 2: 3 values"));
  CHECK_THROWS_WITH(parse_csv_data("x,y\n1,nan\n", "d.csv"), "d.csv line 2, column y: 'nan' is not a finite number");
  CHECK_THROWS_WITH(parse_csv_data("x,y\n-inf,1\n", "d.csv"), Contains("column x: '-inf' is not a finite number"));
  CHECK_THROWS_WITH(parse_csv_data("x,y\n1e999,1\n", "d.csv"), Contains("column x: '1e999' is out of range"));
  CHECK_THROWS_WITH(parse_csv_data("x,y\n,1\n", "d.csv"), Contains("line 2, column x: empty value"));
  // Raw bytes are escaped; a header of many columns is listed in part.
  CHECK_THROWS_WITH(parse_csv_data("x,y\n1,\x1b[2J\n", "d.csv"), Contains("'\\x1b[2J' is not a number"));
  CHECK_THROWS_WITH(parse_csv_data("a,b,c,d,e,f,g,h,i,j\n", "d.csv"), Contains("'g', 'h', ...)"));
}

TEST_CASE("NIST .dat: the table must have the rows its header announces", "[data-set][nist][bad-input]") {
  const std::string norris = nist_text("Norris");
  const DataSet whole = parse_nist_data(norris, "Norris.dat");
  REQUIRE(whole.x.size() == 36);  // "36 Observations"
  CHECK(whole.x(0) == 0.2);  // the first row, "0.1  0.2" (y x)
  CHECK(whole.y(35) == 0.2);  // the last row, "0.2  0.5"
  CHECK(whole.x(35) == 0.5);
  CHECK(whole.certified);
  // Truncated (15 of 36 rows) and one row too many.
  CHECK_THROWS_WITH(parse_nist_data(with_first_rows(norris, 15), "Norris.dat"),
                    "Norris.dat: the header says 36 observations, but the data table below line 60 has 15 rows");
  CHECK_THROWS_WITH(parse_nist_data(norris + "\n  1.0  2.0\n", "Norris.dat"), Contains("has 37 rows"));
  // No count in the header: the table cannot be checked, so the file is not taken as NIST's.
  std::string uncounted = norris;
  uncounted.replace(uncounted.find("36 Observations"), 15, "Observations   ");
  CHECK_THROWS_WITH(parse_nist_data(uncounted, "Norris.dat"), Contains("no 'N Observations' line"));
  std::string bad_count = norris;
  bad_count.replace(bad_count.find("36 Observations"), 2, "3x");
  CHECK_THROWS_WITH(parse_nist_data(bad_count, "Norris.dat"), Contains("'3x' is not a number of observations"));
}

TEST_CASE("NIST .dat: a byte-order mark and CRLF line ends read the same numbers", "[data-set][nist]") {
  std::string crlf;
  for (const char c : nist_text("Pontius")) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  const DataSet plain = parse_nist_data(nist_text("Pontius"), "Pontius.dat");
  const DataSet marked = parse_nist_data("\xEF\xBB\xBF" + crlf, "Pontius.dat");
  CHECK(marked.x == plain.x);
  CHECK(marked.y == plain.y);
  REQUIRE(marked.certified);
  CHECK(marked.certified->parameters == plain.certified->parameters);
  CHECK(marked.certified->r_squared == plain.certified->r_squared);
}

TEST_CASE("Data files that are not files, or too long, are named as such", "[data-set][bad-input]") {
  const auto folder = std::filesystem::temp_directory_path() / "numlab-test-data-set.csv";
  std::filesystem::create_directories(folder);
  CHECK_THROWS_WITH(read_data_file(folder.string()), folder.string() + ": is a directory, not a file");
  std::filesystem::remove_all(folder);
  CHECK_THROWS_WITH(read_data_file("/dev/zero"), "/dev/zero: longer than the 16 MiB limit for input files");
  CHECK_THROWS_WITH(read_nist_data("/dev/zero"), Contains("16 MiB"));
}
