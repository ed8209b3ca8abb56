#include "sandbox.hpp"

#include <sys/stat.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

namespace numlab::robustness {

namespace fs = std::filesystem;

namespace {

const std::string bom = "\xEF\xBB\xBF";
const std::string csv_rows = "0,1\n1,3\n2,5\n3,7.1\n4,8.9\n";

// Files every case finds in its folder, by name and contents.
// A four-bar description (docs/linkage-files.md) with `change` applied: each pair replaces the
// first occurrence of its first string by its second. Line numbers: [ground] 4, O 5, Q 6,
// [joints] 8, A 9, B 10, links at 12-14, 16-18, 20-22, [driver] 24.
std::string four_bar(const std::vector<std::pair<std::string, std::string>>& change = {}) {
  std::string text =
      "[linkage]\nname = \"four-bar\"\n\n"
      "[ground]\nO = [0.0, 0.0]\nQ = [4.0, 0.0]\n\n"
      "[joints]\nA = [0.87, 0.5]\nB = [3.4, 2.9]\n\n"
      "[[link]]\njoints = [\"O\", \"A\"]\nlength = 1.0\n\n"
      "[[link]]\njoints = [\"A\", \"B\"]\nlength = 3.5\n\n"
      "[[link]]\njoints = [\"Q\", \"B\"]\nlength = 3.0\n\n"
      "[driver]\ntype = \"crank\"\npivot = \"O\"\njoint = \"A\"\nangle = 30.0\n";
  for (const auto& [from, to] : change) {
    const std::size_t at = text.find(from);
    if (at == std::string::npos) throw std::logic_error("four_bar: no '" + from + "'");
    text.replace(at, from.size(), to);
  }
  return text;
}

// Linkage description files, each breaking one rule of docs/linkage-files.md and named for what is wrong with it.
// A key or table header of 200,000 parts, "a.a.a...": toml++ overflowed its stack on them.
std::string deeply_nested(const std::string& first, const std::string& last) {
  std::string text = first;
  for (int k = 1; k < 200'000; ++k) text += ".a";
  return text + last;
}

// The four-bar of four_bar() with every coordinate and length multiplied by `scale` (a mechanism in
// other units: its verdicts must not change).
std::string scaled_four_bar(double scale) {
  const auto n = [scale](double v) {
    std::ostringstream out;
    out.precision(17);
    out << v * scale;
    std::string text = out.str();
    return text.find_first_of(".e") == std::string::npos ? text + ".0" : text;
  };
  return "[linkage]\nname = \"four-bar\"\n\n[ground]\nO = [0.0, 0.0]\nQ = [" + n(4.0) + ", 0.0]\n\n[joints]\nA = [" + n(0.87) +
         ", " + n(0.5) + "]\nB = [" + n(3.4) + ", " + n(2.9) + "]\n\n[[link]]\njoints = [\"O\", \"A\"]\nlength = " + n(1.0) +
         "\n\n[[link]]\njoints = [\"A\", \"B\"]\nlength = " + n(3.5) + "\n\n[[link]]\njoints = [\"Q\", \"B\"]\nlength = " +
         n(3.0) + "\n\n[driver]\ntype = \"crank\"\npivot = \"O\"\njoint = \"A\"\nangle = 30.0\n";
}

std::vector<std::pair<std::string, std::string>> linkage_inputs() {
  // Issue 30 §1: an inverted slider-crank whose rocker B-C carries the block A in its slot (the
  // slider's table is added below), and the same with a joint D that no link holds.
  const auto inverted_slider_crank = [](const std::string& more_joints) {
    return "[linkage]\nname = \"isc\"\n[ground]\nO = [0.0, 0.0]\nB = [3.0, 0.0]\n[joints]\nA = [0.5, 0.87]\nC = [-1.73, 1.64]\n" +
           more_joints + "[[link]]\njoints = [\"O\", \"A\"]\nlength = 1.0\n[[link]]\nname = \"rocker\"\njoints = [\"B\", \"C\"]\nlength = 5.0\n";
  };
  const std::string isc = inverted_slider_crank(""), isc_with_d = inverted_slider_crank("D = [1.0, 1.0]\n");
  const std::string isc_crank = "[driver]\ntype = \"crank\"\npivot = \"O\"\njoint = \"A\"\nangle = 60.0\n";
  // A boom: the bar O-P-T (three points on one line) turned about O by an actuator from G (the driver, below).
  const std::string boom = "[linkage]\nname = \"boom\"\n[ground]\nO = [0.0, 0.0]\nG = [1.0, 0.0]\n[joints]\nP = [0.88, 1.8]\n"
                           "T = [1.32, 2.69]\n[[body]]\nname = \"boom\"\njoints = [\"O\", \"P\", \"T\"]\n"
                           "local = [[0.0, 0.0], [2.0, 0.0], [3.0, 0.0]]\n";
  // four_bar()'s crank, to be replaced by a motor at A between the crank and the coupler.
  const std::string four_bar_crank = "type = \"crank\"\npivot = \"O\"\njoint = \"A\"\nangle = 30.0";
  const std::string body = "\n[[body]]\nname = \"plate\"\njoints = [\"A\", \"B\", \"C\"]\n";
  const std::string triangle_links =
      "\n[[link]]\njoints = [\"A\", \"C\"]\nlength = 1.2\n\n[[link]]\njoints = [\"B\", \"C\"]\nlength = 3.7\n";
  return {
      {"lk-four-bar.toml", four_bar()},
      {"lk-syntax.toml", four_bar({{"length = 3.5", "length = = 3.5"}})},
      {"lk-unknown-joint.toml", four_bar({{"[\"Q\", \"B\"]", "[\"Q\", \"X\"]"}})},
      {"lk-duplicate-joint.toml", four_bar({{"B = [3.4, 2.9]", "B = [3.4, 2.9]\nO = [1.0, 1.0]"}})},
      {"lk-self-link.toml", four_bar({{"[\"A\", \"B\"]", "[\"A\", \"A\"]"}})},
      {"lk-zero-length.toml", four_bar({{"length = 3.5", "length = 0.0"}})},
      {"lk-negative-length.toml", four_bar({{"length = 3.5", "length = -3.5"}})},
      {"lk-nan-length.toml", four_bar({{"length = 3.5", "length = nan"}})},
      {"lk-inf-length.toml", four_bar({{"length = 3.5", "length = inf"}})},
      {"lk-body-two-joints.toml", four_bar() + "\n[[body]]\njoints = [\"A\", \"B\"]\nlocal = [[0.0, 0.0], [3.5, 0.0]]\n"},
      {"lk-body-collinear.toml",
       four_bar({{"B = [3.4, 2.9]", "B = [3.4, 2.9]\nC = [2.0, 2.0]"}}) + body + "local = [[0.0, 0.0], [1.0, 0.0], [2.0, 0.0]]\n"},
      {"lk-driver-not-ground.toml", four_bar({{"pivot = \"O\"", "pivot = \"B\""}})},
      {"lk-not-assembling.toml", four_bar({{"length = 3.5", "length = 0.05"}})},  // A-B + B-Q < |AQ| at 30 deg
      {"lk-mobility-2.toml", four_bar({{"[[link]]\njoints = [\"Q\", \"B\"]\nlength = 3.0\n", ""}})},
      {"lk-over-constrained.toml", four_bar() + "\n[[link]]\njoints = [\"O\", \"B\"]\nlength = 3.6\n"},
      // The authoring checks (docs/linkage-files.md): valid files that do not say what they mean.
      {"lk-warn-length.toml", four_bar({{"length = 3.5", "length = 3.0"}})},
      {"lk-crank-radians.toml", four_bar({{"angle = 30.0", "angle = 0.5236"}})},
      {"lk-redundant.toml", four_bar({{"B = [3.4, 2.9]", "B = [3.4, 2.9]\nC = [1.43, 2.44]"}}) + body +
                                "local = [[0.0, 0.0], [3.5, 0.0], [1.75, 1.0]]\n"},
      // The triangle A, B, C already made by links A-B, A-C (1.2) and B-C (3.7), then a body over it.
      {"lk-redundant-body.toml", four_bar({{"B = [3.4, 2.9]", "B = [3.4, 2.9]\nC = [0.04, 1.37]"}}) + triangle_links + body +
                                     "local = [[0.0, 0.0], [3.5, 0.0], [0.0, 1.2]]\n"},
      {"lk-contradicting-body.toml", four_bar({{"B = [3.4, 2.9]", "B = [3.4, 2.9]\nC = [0.04, 1.37]"}}) + triangle_links +
                                         body + "local = [[0.0, 0.0], [3.5, 0.0], [0.0, 1.4]]\n"},
      {"lk-mirrored-body.toml", four_bar({{"B = [3.4, 2.9]", "B = [3.4, 2.9]\nC = [1.43, 2.44]"},
                                          {"[[link]]\njoints = [\"A\", \"B\"]\nlength = 3.5\n", ""}}) +
                                    body + "local = [[0.0, 0.0], [3.5, 0.0], [1.75, -1.0]]\n"},
      {"lk-not-a-linkage.toml", "[table]\nkey = 1\n"},
      {"lk-empty.toml", ""},
      {"sc-four-bar-1e7.toml", scaled_four_bar(1e7)},
      {"sc-four-bar-1e8.toml", scaled_four_bar(1e8)},
      {"sc-four-bar-1e-8.toml", scaled_four_bar(1e-8)},
      {"sc-four-bar-1e-12.toml", scaled_four_bar(1e-12)},
      {"sc-four-bar-1e-300.toml", scaled_four_bar(1e-300)},
      {"sc-four-bar-1e300.toml", scaled_four_bar(1e300)},
      // Not Grashof (crank 2, coupler 3, rocker 2.5, ground 4: 2 + 4 > 3 + 2.5): the crank stops at
      // 129.83 deg, where |AQ| = 3 + 2.5.
      {"lk-non-grashof.toml", four_bar({{"A = [0.87, 0.5]", "A = [1.732, 1.0]"}, {"B = [3.4, 2.9]", "B = [4.34, 2.48]"},
                                        {"length = 1.0", "length = 2.0"}, {"length = 3.0", "length = 2.5"},
                                        {"length = 3.5", "length = 3.0"}})},
      // Issue 30 §2: a link's name and the linkage's output (an unknown one, a name taken twice, a good one).
      {"lk-output-unknown.toml", four_bar({{"name = \"four-bar\"", "name = \"four-bar\"\noutput = \"B\""}})},
      {"lk-link-name-twice.toml", four_bar({{"[[link]]\njoints = [\"A\", \"B\"]", "[[link]]\nname = \"O-A\"\njoints = [\"A\", \"B\"]"}})},
      {"lk-output.toml", four_bar({{"name = \"four-bar\"", "name = \"four-bar\"\noutput = \"rocker\""},
                                   {"[[link]]\njoints = [\"Q\", \"B\"]", "[[link]]\nname = \"rocker\"\njoints = [\"Q\", \"B\"]"}})},
      // Issue 30 §4: the paths the drawing highlights ([linkage] trace), good and bad.
      {"lk-trace.toml", four_bar({{"name = \"four-bar\"", "name = \"four-bar\"\ntrace = [\"B\"]"}})},
      {"lk-trace-unknown.toml", four_bar({{"name = \"four-bar\"", "name = \"four-bar\"\ntrace = [\"X\"]"}})},
      {"lk-trace-ground.toml", four_bar({{"name = \"four-bar\"", "name = \"four-bar\"\ntrace = [\"O\"]"}})},
      {"lk-trace-not-list.toml", four_bar({{"name = \"four-bar\"", "name = \"four-bar\"\ntrace = \"B\""}})},
      {"lk-trace-twice.toml", four_bar({{"name = \"four-bar\"", "name = \"four-bar\"\ntrace = [\"B\", \"B\"]"}})},
      {"lk-slider-driven.toml", "[linkage]\nname = \"s\"\n[ground]\nO = [0.0, 0.0]\n[joints]\nA = [0.9, 0.5]\nS = [2.9, 0.25]\n"
                                "[[link]]\njoints = [\"O\", \"A\"]\nlength = 1.0\n[[link]]\njoints = [\"A\", \"S\"]\nlength = 2.0\n"
                                "[[slider]]\njoint = \"S\"\nthrough = [0.0, 0.25]\n[driver]\ntype = \"slider\"\njoint = \"S\"\ntravel = 2.9\n"},
      // Issue 30 §3: loads ([[load]]) and the driving torque; each bad one refused at its place.
      {"lk-path.csv", "crank_deg,crank2_deg\n90,90\n60,120\n30,100\n"},  // a --drivers path for five-bar
      {"lk-loads.toml", four_bar() + "\n[[load]]\nlink = \"Q-B\"\ntorque = -10.0\n\n[[load]]\njoint = \"B\"\nmass = 2.0\n"},
      {"lk-slider-load.toml", "[linkage]\nname = \"s\"\n[ground]\nO = [0.0, 0.0]\n[joints]\nA = [0.9, 0.5]\nS = [2.9, 0.25]\n"
                              "[[link]]\njoints = [\"O\", \"A\"]\nlength = 1.0\n[[link]]\njoints = [\"A\", \"S\"]\nlength = 2.0\n"
                              "[[slider]]\njoint = \"S\"\nthrough = [0.0, 0.25]\n[driver]\ntype = \"slider\"\njoint = \"S\"\ntravel = 2.9\n"
                              "[[load]]\nlink = \"O-A\"\ntorque = 5.0\n"},
      {"lk-parallelogram-load.toml", four_bar({{"Q = [4.0, 0.0]", "Q = [3.5, 0.0]"}, {"B = [3.4, 2.9]", "B = [4.37, 0.5]"},
                                               {"length = 3.0", "length = 1.0"}}) +
                                         "\n[[load]]\nlink = \"Q-B\"\ntorque = 1.0\n"},
      {"lk-load-unknown-joint.toml", four_bar() + "\n[[load]]\njoint = \"X\"\nforce = [0.0, -10.0]\n"},
      {"lk-load-unknown-link.toml", four_bar() + "\n[[load]]\nlink = \"crank\"\ntorque = 2.5\n"},
      {"lk-load-both.toml", four_bar() + "\n[[load]]\njoint = \"B\"\nlink = \"O-A\"\ntorque = 2.5\n"},
      {"lk-load-neither.toml", four_bar() + "\n[[load]]\nforce = [1.0, 2.0]\n"},
      {"lk-load-force-and-mass.toml", four_bar() + "\n[[load]]\njoint = \"B\"\nforce = [1.0, 2.0]\nmass = 2.0\n"},
      {"lk-load-torque-at-joint.toml", four_bar() + "\n[[load]]\njoint = \"B\"\ntorque = 2.0\n"},
      {"lk-load-force-on-link.toml", four_bar() + "\n[[load]]\nlink = \"A-B\"\nforce = [1.0, 2.0]\ntorque = 1.0\n"},
      {"lk-load-negative-mass.toml", four_bar() + "\n[[load]]\njoint = \"B\"\nmass = -2.0\n"},
      {"lk-load-force-one.toml", four_bar() + "\n[[load]]\njoint = \"B\"\nforce = [1.0]\n"},
      {"lk-load-force-nan.toml", four_bar() + "\n[[load]]\njoint = \"B\"\nforce = [nan, 1.0]\n"},
      {"lk-load-unknown-key.toml", four_bar() + "\n[[load]]\njoint = \"B\"\nforce = [1.0, 0.0]\nat = 3\n"},
      {"lk-load-table.toml", four_bar() + "\n[load]\njoint = \"B\"\nforce = [1.0, 0.0]\n"},
      {"lk-load-no-torque.toml", four_bar() + "\n[[load]]\nlink = \"A-B\"\n"},
      {"lk-load-torque-string.toml", four_bar() + "\n[[load]]\nlink = \"A-B\"\ntorque = \"2\"\n"},
      {"lk-gravity-negative.toml", four_bar({{"name = \"four-bar\"", "name = \"four-bar\"\ngravity = -9.8"}}) +
                                       "\n[[load]]\njoint = \"B\"\nmass = 1.0\n"},
      {"lk-gravity-string.toml", four_bar({{"name = \"four-bar\"", "name = \"four-bar\"\ngravity = \"down\""}})},
      // Issue 30 §1: a slider in a moving link's slot, an actuator, a motor, a bar of collinear points.
      {"lk-slot.toml", isc + "[[slider]]\njoint = \"A\"\nline = [\"B\", \"C\"]\n" + isc_crank},
      {"lk-slot-and-through.toml", isc_with_d + "[[slider]]\njoint = \"A\"\nline = [\"B\", \"C\"]\nthrough = [0.0, 0.0]\n" + isc_crank},
      {"lk-slot-not-on-link.toml", isc_with_d + "[[slider]]\njoint = \"A\"\nline = [\"B\", \"D\"]\n" + isc_crank},
      {"lk-slot-own-joint.toml", isc_with_d + "[[slider]]\njoint = \"C\"\nline = [\"B\", \"C\"]\n" + isc_crank},
      {"lk-boom.toml", boom + "[driver]\ntype = \"actuator\"\njoints = [\"G\", \"P\"]\nlength = 1.8\n[[load]]\njoint = \"T\"\nmass = 10.0\n"},
      {"lk-actuator-linked.toml", boom + "[driver]\ntype = \"actuator\"\njoints = [\"O\", \"P\"]\nlength = 1.8\n"},
      {"lk-actuator-zero.toml", boom + "[driver]\ntype = \"actuator\"\njoints = [\"G\", \"P\"]\nlength = 0.0\n"},
      {"lk-motor.toml", four_bar({{four_bar_crank, "type = \"motor\"\npivot = \"A\"\nfrom = \"O\"\njoint = \"B\"\nangle = -166.4"}})},
      {"lk-motor-wrong-angle.toml", four_bar({{four_bar_crank, "type = \"motor\"\npivot = \"A\"\nfrom = \"O\"\njoint = \"B\"\nangle = 13.6"}})},
      {"lk-motor-same-link.toml", four_bar({{four_bar_crank, "type = \"motor\"\npivot = \"A\"\nfrom = \"B\"\njoint = \"B\"\nangle = 10.0"}})},
      {"lk-deep-key.toml", deeply_nested("a", " = 1\n")},
      {"lk-deep-header.toml", deeply_nested("[a", "]\n")},
      // Titles with a C1 control (U+009B, a CSI), a direction override (U+202E), an isolate (U+2066).
      {"lk-title-c1.toml", four_bar({{"name = \"four-bar\"", "name = \"four-bar\"\ntitle = \"a\xc2\x9b" "2Jb\""}})},
      {"lk-title-bidi.toml", four_bar({{"name = \"four-bar\"", "name = \"four-bar\"\ntitle = \"a\xe2\x80\xae" "cba\""}})},
      {"lk-title-isolate.toml", four_bar({{"name = \"four-bar\"", "name = \"four-bar\"\ntitle = \"a\xe2\x81\xa6" "b\""}})},
  };
}

// x = 0, 1, ..., 999 and y = sqrt(x): power sums of x to high powers overflow.
std::string wide_x_csv() {
  std::string text = "x,y\n";
  for (int i = 0; i < 1000; ++i) text += std::to_string(i) + "," + std::to_string(std::sqrt(i)) + "\n";
  return text;
}

std::vector<std::pair<std::string, std::string>> text_inputs() {
  std::vector<std::pair<std::string, std::string>> files = {
      // Matrix files (docs/cli.md, solve linear --matrix).
      {"a2.txt", "4 1\n1 3\n"},
      {"aug3.txt", "4 1 0 5\n1 4 1 6\n0 1 4 5\n"},
      {"rhs2.txt", "5\n4\n"},
      {"rhs3.txt", "1\n2\n3\n"},
      {"bom.txt", bom + "4 1\n1 3\n"},
      {"crlf.txt", "4 1\r\n1 3\r\n"},
      {"emptycell.txt", "1,,2\n3,4\n"},
      {"escape.txt", "4 1\n1 \x1b]0;pwned\x07\n"},
      {"csi.txt", "\x1b[2J\x1b[31m4 1\n1 3\n"},
      {"carriage.txt", "4 1\n1 3x\rnumlab: fine\n"},
      {"nul.txt", std::string("4 1\n1 3\0 9\n", 11)},
      {"fullwidth.txt", "4 1\n1 \xEF\xBC\x93\n"},
      {"nan.txt", "nan 1\n1 3\n"},
      {"inf.txt", "inf 1\n1 3\n"},
      {"overflow.txt", "1e400 1\n1 3\n"},
      {"huge.txt", "1e300 0\n0 1e300\n"},
      {"tiny.txt", "1e-320 0\n0 1e-320\n"},
      {"singular.txt", "1 2\n2 4\n"},
      {"inconsistent.txt", "1 1 1\n1 1 2\n"},  // [A | b]: x1 + x2 = 1 and x1 + x2 = 2
      {"nonsquare.txt", "1 2 3\n4 5 6\n7 8 9\n10 11 12\n"},
      {"ragged.txt", "1 2\n3\n"},
      {"empty.txt", ""},
      {"comments.txt", "# only a comment\n"},
      {"one.txt", "5\n"},
      // CSV data sets (fit --data).
      {"mydata.csv", "x,y\n" + csv_rows},
      {"bom.csv", bom + "x,y\n" + csv_rows},
      {"crlf.csv", "x,y\r\n0,1\r\n1,3\r\n2,5\r\n"},
      {"nan.csv", "x,y\n0,1\n1,nan\n2,5\n3,7\n"},
      {"inf.csv", "x,y\n0,1\n1,inf\n2,5\n3,7\n"},
      {"text.csv", "x,y\n0,1\n1,abc\n2,5\n"},
      {"escape.csv", "x,y\n0,1\n1,\x1b]0;pwned\x07\n"},
      {"emptycell.csv", "x,y\n0,,1\n1,3\n2,5\n"},
      {"nocols.csv", "a,b\n1,2\n3,4\n"},
      {"header.csv", "x,y\n"},
      {"samex.csv", "x,y\n1,1\n1,2\n1,3\n"},
      {"hugey.csv", "x,y\n0,1e300\n1,-1e300\n2,1e300\n3,-1e300\n"},
      {"widex.csv", wide_x_csv()},
      {"bigx.csv", "x,y\n1e200,2.1\n2e200,2.9\n3e200,4.2\n4e200,4.8\n5e200,6.1\n6e200,7.0\n7e200,7.9\n"},
      // Not a NIST file, though named like one.
      {"noheader.dat", "hello\n"},
  };
  for (auto& file : linkage_inputs()) files.push_back(std::move(file));
  return files;
}

std::string read_bytes(const fs::path& path) {
  std::ifstream file(path, std::ios::binary);
  std::ostringstream contents;
  contents << file.rdbuf();
  return contents.str();
}

void write_bytes(const fs::path& path, const std::string& contents) {
  std::ofstream file(path, std::ios::binary);
  file << contents;
  if (!file.flush()) throw std::runtime_error("cannot write " + path.string());
}

// Every byte value once, then the escape sequences that retitle or clear a terminal.
std::string binary_garbage() {
  std::string bytes;
  for (int b = 0; b < 256; ++b) bytes += static_cast<char>(b);
  return bytes + "\x1b]0;title\x07\x1b[2J\x1b[1;31m\r\n\xff\xfe";
}

// The first `keep` lines of a NIST file: its header still promises every row.
std::string first_lines(const std::string& text, int keep) {
  std::size_t end = 0;
  for (int line = 0; line < keep && end < text.size(); ++line) {
    const std::size_t newline = text.find('\n', end);
    end = newline == std::string::npos ? text.size() : newline + 1;
  }
  return text.substr(0, end);
}

// One row of 200 000 numbers.
std::string long_row() {
  std::string row;
  for (int i = 0; i < 200000; ++i) row += "1 ";
  return row + "\n";
}

std::string hash_of(const std::string& bytes) {
  std::uint64_t hash = 14695981039346656037ull;  // FNV-1a, 64 bits
  for (const char c : bytes) {
    hash ^= static_cast<unsigned char>(c);
    hash *= 1099511628211ull;
  }
  return std::to_string(bytes.size()) + ":" + std::to_string(hash);
}

}  // namespace

void prepare_inputs(const std::string& folder, const std::string& nist_dir) {
  // 1. Small text inputs.
  for (const auto& [name, contents] : text_inputs()) write_bytes(fs::path(folder) / name, contents);
  // 2. Binary garbage and a very long row.
  write_bytes(fs::path(folder) / "binary.bin", binary_garbage());
  write_bytes(fs::path(folder) / "longrow.txt", long_row());
  // 3. NIST data sets: Norris whole, and Norris cut to 15 of its 36 rows (data from line 61).
  const std::string norris = read_bytes(fs::path(nist_dir) / "Norris.dat");
  if (norris.empty()) throw std::runtime_error("cannot read Norris.dat in " + nist_dir);
  write_bytes(fs::path(folder) / "Norris.dat", norris);
  write_bytes(fs::path(folder) / "truncated.dat", first_lines(norris, 60 + 15));
  // 4. A folder, a folder named like a chart, and a pipe nobody writes to.
  fs::create_directory(fs::path(folder) / "adir");
  fs::create_directory(fs::path(folder) / "svgdir.svg");
  if (mkfifo((fs::path(folder) / "fifo").c_str(), 0600) != 0) throw std::runtime_error("mkfifo failed");
  // 5. A lab's folder that exists but takes no files, even for root: closed/lab-gauss -> /proc/self.
  fs::create_directory(fs::path(folder) / "closed");
  fs::create_directory_symlink("/proc/self", fs::path(folder) / "closed" / "lab-gauss");
}

std::map<std::string, std::string> snapshot_tree(const std::string& folder) {
  std::map<std::string, std::string> entries;
  std::error_code error;
  for (fs::recursive_directory_iterator it(folder, error), end; it != end; it.increment(error)) {
    if (error) break;
    const std::string name = fs::relative(it->path(), folder).string();
    const fs::file_status status = it->symlink_status();
    if (fs::is_symlink(status)) {
      entries[name] = "link -> " + fs::read_symlink(it->path()).string();
    } else if (fs::is_directory(status)) {
      entries[name] = "dir";
    } else if (fs::is_regular_file(status)) {
      entries[name] = hash_of(read_bytes(it->path()));
    } else {
      entries[name] = "other";
    }
  }
  return entries;
}

std::set<std::string> list_names(const std::string& folder) {
  std::set<std::string> names;
  std::error_code error;
  for (fs::directory_iterator it(folder, error), end; it != end; it.increment(error)) {
    if (error) break;
    names.insert(it->path().filename().string());
  }
  return names;
}

}  // namespace numlab::robustness
