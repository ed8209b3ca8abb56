#include "output/format.hpp"

#include "output/exit_codes.hpp"

#include <cmath>

namespace numlab::cli {

nlohmann::ordered_json number_or_null(double value) {
  return std::isfinite(value) ? nlohmann::ordered_json(value) : nlohmann::ordered_json();
}

int exit_code_for(Status status) { return status == Status::converged ? exit_success : exit_method_failed; }

}  // namespace numlab::cli
