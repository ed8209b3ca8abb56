// libFuzzer target: numlab::fitting::parse_nist_data, the reader of NIST StRD `.dat` files.

#include "fuzz_data_set.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace numlab;
  return fuzz::run_parser(
      [&] { fuzz::check_data_set(fitting::parse_nist_data(fuzz::as_text(data, size), "fuzz.dat")); });
}
