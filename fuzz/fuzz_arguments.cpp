// libFuzzer target: the command line's number arguments (labs/parsing/argument_parsing). The first byte
// picks the parser (its value modulo 4: 0 --sweep, 1 --x0, 2 --generate, 3 --crank); the rest is
// the argument's text. The seeds in corpus/arguments/ start with the digits '0' ... '3'.

#include <cmath>
#include <string>
#include <vector>

#include "parsing/argument_parsing.hpp"
#include "fuzz_target.hpp"

namespace {

using namespace numlab;

void sweep(std::string_view text) {
  const cli::DegreeRange range = cli::parse_degree_range(text, "--sweep");
  fuzz::require(std::isfinite(range.start) && std::isfinite(range.stop) && std::isfinite(range.step),
                "a non-finite sweep bound");
  fuzz::require(range.step != 0.0 && (range.stop - range.start) * range.step >= 0.0, "a step that does not move");
  fuzz::require((range.stop - range.start) / range.step < cli::max_sweep_poses, "more poses than the cap");
}

void point(std::string_view text) {
  const std::vector<double> values = cli::parse_number_list(text, "--x0");
  fuzz::require(!values.empty(), "an empty list");
  for (const double value : values) fuzz::require(std::isfinite(value), "a non-finite item");
}

void generate(std::string_view text) {
  static const std::vector<std::string> kinds = {"random", "hilbert", "wilkinson", "diag-dominant", "gs-diverge",
                                                 "singular"};
  const cli::GeneratorSpec spec = cli::parse_generator_spec(text, kinds, "gs-diverge", 4096, "--generate");
  fuzz::require(spec.size ? *spec.size >= 1 && *spec.size <= 4096 : spec.kind == "gs-diverge", "a size off the range");
}

void crank(std::string_view text) {
  const std::string problem = cli::finite_number_problem(text);
  if (problem.empty()) fuzz::require(std::isfinite(cli::parse_finite_number(text)), "a non-finite crank angle");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string_view text = fuzz::as_text(data + 1, size - 1);
  return fuzz::run_parser([&] {
    switch (data[0] % 4) {
      case 0: return sweep(text);
      case 1: return point(text);
      case 2: return generate(text);
      default: return crank(text);
    }
  });
}
