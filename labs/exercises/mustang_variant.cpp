#include "exercises/mustang_variant.hpp"

#include <fmt/format.h>

#include <cmath>

#include "exercises/jansen_poses.hpp"
#include "numlab/mechanisms/mustang_linkage.hpp"

namespace numlab::exercises {

namespace {

using mechanisms::MustangLengths;
using mechanisms::MustangLinkage;

// Bisection on a predicate true at `yes` and false at `no`, to 1e-9 deg.
template <typename Predicate>
double bisect(double yes, double no, Predicate holds) {
  while (std::abs(no - yes) > 1e-9) {
    const double middle = 0.5 * (yes + no);
    (holds(middle) ? yes : no) = middle;
  }
  return yes;
}

// The closure's independent lengths, by the protocol's names; the tied ones follow them.
LinkLengths independent(const MustangLengths& L) {
  return {{"l1_3", L.l1_3}, {"l3_4", L.l3_4}, {"l2_4", L.l2_4}, {"l0_5", L.l0_5}, {"l5_6", L.l5_6},
          {"l6_7", L.l6_7}, {"l6_8", L.l6_8}, {"l8_9", L.l8_9}, {"l7_10", L.l7_10}, {"l10_8", L.l10_8}};
}

MustangLengths lengths_from(const LinkLengths& list) {
  MustangLengths L;
  for (auto [name, field] : {std::pair{"l1_3", &L.l1_3}, {"l3_4", &L.l3_4}, {"l2_4", &L.l2_4}, {"l0_5", &L.l0_5},
                             {"l5_6", &L.l5_6}, {"l6_7", &L.l6_7}, {"l6_8", &L.l6_8}, {"l8_9", &L.l8_9},
                             {"l7_10", &L.l7_10}, {"l10_8", &L.l10_8}}) {
    *field = length_named(list, name);
  }
  L.l4_6 = L.l2_4;      // the bend 2-4-6 stays isosceles: |2 6| = 2 |2 4| cos b
  L.l10_11 = L.l10_8;   // loop 4 stays a kite
  L.l9_11 = L.l8_9;
  return L;
}

}  // namespace

LinkLengths MustangVariant::named() const {
  const MustangLengths& L = lengths;
  return {{"l1_3", L.l1_3}, {"l3_4", L.l3_4},   {"l2_4", L.l2_4},   {"l4_6", L.l4_6},   {"l0_5", L.l0_5},
          {"l5_6", L.l5_6}, {"l6_7", L.l6_7},   {"l6_8", L.l6_8},   {"l8_9", L.l8_9},   {"l7_10", L.l7_10},
          {"l10_8", L.l10_8}, {"l10_11", L.l10_11}, {"l9_11", L.l9_11}};
}

std::optional<MustangVariant> mustang_geometry(const MustangLengths& lengths) {
  const MustangLinkage linkage(lengths);
  const auto assembles = [&linkage](double deg) { return linkage.closed_form(deg * degrees).status == Status::converged; };
  if (!assembles(0.0) || !assembles(45.0) || assembles(-90.0) || assembles(90.0)) return std::nullopt;
  MustangVariant found;
  found.lengths = lengths;
  found.lower_deg = bisect(0.0, -90.0, assembles);
  found.upper_deg = bisect(45.0, 90.0, assembles);
  // P8's side of the line P9 -> P10 (where the open and the folded kite meet, it changes).
  const auto side = [&linkage](double deg) {
    const auto p = linkage.closed_form(deg * degrees).joints;
    const Eigen::Vector2d a = p[10] - p[9], b = p[8] - p[9];
    return a.x() * b.y() - a.y() * b.x() > 0.0;
  };
  int changes = 0;
  double below = found.lower_deg;
  const double first = std::ceil(found.lower_deg * 4.0) / 4.0, last = std::floor(found.upper_deg * 4.0) / 4.0;
  for (double deg = first; deg <= last; deg += 0.25) {
    if (!assembles(deg)) return std::nullopt;
    if (deg > first && side(deg) != side(deg - 0.25)) {
      ++changes;
      below = deg - 0.25;
    }
  }
  if (changes != 1) return std::nullopt;
  const bool side_below = side(below);
  found.crossing_deg = bisect(below, below + 0.25, [&](double deg) { return side(deg) == side_below; });
  return found;
}

MustangVariant mustang_variant(const Variant& variant, const std::function<bool(const MustangVariant&)>& valid) {
  if (!variant.active()) return MustangVariant{};
  std::optional<MustangVariant> chosen;
  const LinkLengths drawn = variant_lengths(variant, 9, independent(MustangLengths()), [&](const LinkLengths& list) {
    chosen = mustang_geometry(lengths_from(list));
    if (!chosen) return false;
    chosen->varied = true;
    return valid(*chosen);
  });
  chosen = mustang_geometry(lengths_from(drawn));
  chosen->varied = true;
  return *chosen;
}

std::string mustang_variant_task_text(const MustangVariant& linkage) {
  if (!linkage.varied) return "";
  return fmt::format("Your linkage's lengths are not seed 003's: each is within 3% of it (|4 6| = |2 4|, and the kite "
                     "keeps |10 11| = |10 8| and |9 11| = |8 9|; the bend b = pi/9 and P0, P1, P2 are unchanged), and "
                     "every request carries them as `lengths` (use those, not the constants above): {}.\n\n"
                     "So its assembly limits are not seed 003's either: it assembles on the seed's branch for theta "
                     "from {:.4f} to {:.4f} degrees (numlab's closed form, by bisection), and loop 4's kite crosses "
                     "(its Jacobian is singular) at {:.2f} degrees. Task 1's angles near the limits and Task 2's "
                     "angles beyond them move with these limits.\n",
                     lengths_text(linkage.named()), linkage.lower_deg, linkage.upper_deg, linkage.crossing_deg);
}

}  // namespace numlab::exercises
