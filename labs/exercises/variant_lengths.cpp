#include "exercises/variant_lengths.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace numlab::exercises {

LinkLengths variant_lengths(const Variant& variant, unsigned base, const LinkLengths& nominal,
                            const std::function<bool(const LinkLengths&)>& valid) {
  if (!variant.active()) return nominal;
  auto draw = [&nominal](unsigned seed) {
    Variant::Stream stream(0x1e9971a5ULL * seed + 1);
    LinkLengths lengths = nominal;
    for (NamedLength& length : lengths) length.value *= 1.0 + stream.uniform(-length_spread, length_spread);
    return lengths;
  };
  return draw(variant.seed_where(base, [&](unsigned seed) { return valid(draw(seed)); }));
}

double length_named(const LinkLengths& lengths, const std::string& name) {
  for (const NamedLength& length : lengths) {
    if (length.name == name) return length.value;
  }
  throw std::logic_error("no length named " + name);
}

nlohmann::json lengths_json(const LinkLengths& lengths) {
  nlohmann::json json = nlohmann::json::object();
  for (const NamedLength& length : lengths) json[length.name] = length.value;
  return json;
}

std::string lengths_text(const LinkLengths& lengths) {
  std::string text;
  for (const NamedLength& length : lengths) text += fmt::format("{}{} = {:.17g}", text.empty() ? "" : ", ", length.name, length.value);
  return text;
}

}  // namespace numlab::exercises
