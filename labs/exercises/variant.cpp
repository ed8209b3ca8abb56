#include "exercises/variant.hpp"

#include <stdexcept>

namespace numlab::exercises {

namespace {

std::uint64_t fnv1a(const std::string& text) {
  std::uint64_t hash = 0xcbf29ce484222325ULL;
  for (const char c : text) {
    hash ^= static_cast<unsigned char>(c);
    hash *= 0x100000001b3ULL;
  }
  return hash;
}

std::uint64_t splitmix64(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

}  // namespace

std::string variant_id_problem(const std::string& id) {
  if (id.empty()) return "a variant ID must not be empty (e.g. a student number)";
  for (const char c : id) {
    const unsigned char u = static_cast<unsigned char>(c);
    if (u < 0x20 || u == 0x7f) return "a variant ID must not hold control characters (tabs, line breaks, ...)";
  }
  return "";
}

Variant::Variant(std::string id) {
  if (const std::string problem = variant_id_problem(id); !problem.empty()) throw std::invalid_argument(problem);
  id_ = std::move(id);
}

std::uint64_t Variant::Stream::next() { return splitmix64(state_); }

double Variant::Stream::uniform(double low, double high) {
  const double unit = static_cast<double>(next() >> 11) * 0x1.0p-53;  // 53 random bits in [0, 1)
  return low + (high - low) * unit;
}

unsigned Variant::seed(unsigned base) const {
  if (!id_) return base;
  Stream stream = this->stream(base);
  const auto mixed = static_cast<unsigned>(stream.next() >> 32);
  return mixed == base ? mixed + 1 : mixed;  // never the seed without a variant
}

unsigned Variant::seed_where(unsigned base, const std::function<bool(unsigned)>& valid) const {
  if (!id_) return base;
  Stream redraws = stream(base ^ 0x5eed5eedU);
  unsigned candidate = seed(base);
  for (int attempt = 0; attempt < 1000; ++attempt) {
    if (valid(candidate)) return candidate;
    candidate = static_cast<unsigned>(redraws.next() >> 32);
  }
  throw std::logic_error("variant '" + *id_ + "': no valid draw in 1000 for the check of base seed " +
                         std::to_string(base));
}

Variant::Stream Variant::stream(unsigned base) const {
  std::uint64_t state = fnv1a(id_.value_or("")) ^ (static_cast<std::uint64_t>(base) * 0xd1b54a32d192ed03ULL);
  splitmix64(state);
  return Stream(state);
}

}  // namespace numlab::exercises
