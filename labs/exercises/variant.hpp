#pragma once
// A variant per student (issue 29 §4; docs/exercises.md, "Variants"): `exercise init|check|grade
// --variant ID` derives every random matrix, right-hand side, start, crank angle and link length of
// a battery from ID (any non-empty string without control characters, e.g. a student number). The
// same ID gives the same requests, two IDs give different ones, and without an ID every check sends
// exactly the requests it always sent.
//
// The ID's hash is FNV-1a (64 bits) over its bytes, not std::hash (which may differ between builds
// and standard libraries), mixed into each check's base seed by SplitMix64: a variant is the same
// on every machine and every numlab build.

#include <cstdint>
#include <functional>
#include <optional>
#include <string>

namespace numlab::exercises {

class Variant {
 public:
  // Numbers drawn from a variant, for what is not a generator's seed (angles, lengths, data): a
  // SplitMix64 sequence, read as doubles without std:: distributions (which differ between
  // standard libraries).
  class Stream {
   public:
    explicit Stream(std::uint64_t state) : state_(state) {}
    std::uint64_t next();
    double uniform(double low, double high);  // in [low, high)

   private:
    std::uint64_t state_;
  };

  Variant() = default;  // no variant: the checks as they are without --variant
  // std::invalid_argument (one line) when `id` is empty or holds a control character.
  explicit Variant(std::string id);

  bool active() const { return id_.has_value(); }
  const std::optional<std::string>& id() const { return id_; }

  // The seed a check uses where it used `base`: `base` itself without an ID, else a mix of the ID's
  // hash and `base` (another base, another seed).
  unsigned seed(unsigned base) const;
  // seed(base) when `valid` accepts it, else the next of the ID's re-draws that it accepts (a
  // variant stays inside the check's family: a singular matrix singular, a convergent iteration
  // convergent). `base` itself, untested, without an ID. std::logic_error after 1000 re-draws.
  unsigned seed_where(unsigned base, const std::function<bool(unsigned)>& valid) const;
  // The numbers of the check whose base seed is `base` (only meaningful for an active variant).
  Stream stream(unsigned base) const;

 private:
  std::optional<std::string> id_;
};

// "" when `id` may be a variant ID, else why not (for the command line's validators).
std::string variant_id_problem(const std::string& id);

}  // namespace numlab::exercises
