#pragma once
// The Mustang roof linkage a mustang-newton battery checks (issue 29 §4; docs/exercises.md, "A variant
// per student"): seed 003's lengths without a variant; with one, every link of the closure within
// +-3% of seed 003's (variant_lengths.hpp), with the two equalities the closure's form rests on kept:
// |4 6| = |2 4| (the chord |2 6| = 2 |2 4| cos b) and loop 4 a kite (|10 11| = |10 8|, |9 11| =
// |8 9|). The bend b stays pi/9 and the fixed points stay where they are.
//
// A variant's assembly limits and the kite's crossing move with its lengths: they are computed here
// from numlab's closed form (MustangLinkage), as tests/mechanisms/linkage/models/test_mustang_file.cpp
// computes seed 003's: bisection on "the closed form assembles" from 0 deg down and from 45 deg up,
// and on the side of P8 from the line P9 -> P10 (the kite's folded and open branches meet there).

#include <functional>
#include <optional>
#include <string>

#include "exercises/variant.hpp"
#include "exercises/variant_lengths.hpp"
#include "numlab/mechanisms/mustang_closure.hpp"

namespace numlab::exercises {

struct MustangVariant {
  mechanisms::MustangLengths lengths;
  bool varied = false;  // the requests carry `lengths` only then
  // Seed 003's, to the digits TASK.md states (bisection gives them to 1e-4 deg); a variant's, computed.
  double lower_deg = -41.4257, upper_deg = 56.4540;  // the assembly limits on the seed's branch
  double crossing_deg = 43.15;                       // the kite's crossing, where loop 4's J is singular
  // How far a variant's limits are from seed 003's (0 without a variant): the battery's angles near
  // a limit move with it.
  double lower_shift() const { return varied ? lower_deg - -41.4257 : 0.0; }
  double upper_shift() const { return varied ? upper_deg - 56.4540 : 0.0; }
  // The request's `lengths`: l1_3, l3_4, l2_4, l4_6, l0_5, l5_6, l6_7, l6_8, l8_9, l7_10, l10_8, l10_11, l9_11.
  LinkLengths named() const;
};

// The limits and the crossing of the linkage with `lengths`, from numlab's closed form to 1e-9 deg;
// nothing unless it assembles at every quarter degree from the lower limit to the upper (one interval
// through 0 and 45 deg) and the kite crosses once inside it.
std::optional<MustangVariant> mustang_geometry(const mechanisms::MustangLengths& lengths);

// Seed 003's linkage without a variant (untested); with one, the first draw whose geometry exists and
// that `valid` accepts (the battery's own test: every request built, numlab's Newton converging).
MustangVariant mustang_variant(const Variant& variant, const std::function<bool(const MustangVariant&)>& valid);

// TASK.md's words on a variant's linkage ("" when not varied): its lengths, limits and crossing.
std::string mustang_variant_task_text(const MustangVariant& linkage);

}  // namespace numlab::exercises
