// libFuzzer target: numlab::fitting::parse_csv_data, the reader of `fit --data FILE.csv`.

#include "fuzz_data_set.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace numlab;
  return fuzz::run_parser([&] {
    const fitting::DataSet set = fitting::parse_csv_data(fuzz::as_text(data, size), "fuzz.csv");
    fuzz::check_data_set(set);
    fuzz::require(!set.certified, "a CSV file carried certified values");
  });
}
