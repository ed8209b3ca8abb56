#pragma once
// The link lengths of a variant (issue 29 §4; docs/exercises.md, "A variant per student"): with
// `--variant ID` every length of a linkage exercise is its nominal value times 1 + u, u drawn
// uniformly in [-3%, 3%) from the ID's stream, and drawn again until the exercise's own test accepts
// the set (numlab's solver assembles the mechanism at every angle the battery checks). Without an
// ID the nominal lengths, untested, and the requests carry no `lengths` field.

#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "exercises/variant.hpp"

namespace numlab::exercises {

// One length as the protocol names it ("l1", "crank", "a").
struct NamedLength {
  std::string name;
  double value = 0.0;
};
using LinkLengths = std::vector<NamedLength>;

inline constexpr double length_spread = 0.03;  // each length within +-3% of its nominal value

// `nominal` without a variant; else the first draw from the variant's stream for the check of base
// seed `base` that `valid` accepts (Variant::seed_where: std::logic_error after 1000 draws).
LinkLengths variant_lengths(const Variant& variant, unsigned base, const LinkLengths& nominal,
                            const std::function<bool(const LinkLengths&)>& valid);

// The value called `name` (std::logic_error when there is none: a programming error).
double length_named(const LinkLengths& lengths, const std::string& name);

// {"l1": 50.3, ...}: the request's `lengths` field.
nlohmann::json lengths_json(const LinkLengths& lengths);

// "crank = 15.07, l1 = 49.61, ..." with every digit a request carries (17 significant), for TASK.md.
std::string lengths_text(const LinkLengths& lengths);

}  // namespace numlab::exercises
