#pragma once
// How a command prints its result (--format), and JSON's numbers.

#include <nlohmann/json.hpp>

namespace numlab::cli {

enum class Format { text, json, csv };

// A number for JSON output, or null when it is NaN or infinite (JSON has no such numbers).
nlohmann::ordered_json number_or_null(double value);

}  // namespace numlab::cli
