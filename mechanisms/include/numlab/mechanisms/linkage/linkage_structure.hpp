#pragma once
// Before anything is solved: does the description move with one degree of freedom, and does every
// equation have an unknown of its own?
//
//   1. mobility         - Gruebler-Kutzbach, M = 3 (n - 1) - 2 j1 - j2: n members (the ground, every
//                         link, body and slider block, an actuator's cylinder and rod), j1 lower pairs
//                         (a pin where k members meet counts k - 1; a slider adds its prismatic pair,
//                         an actuator its cylinder-rod pair), j2 = 0 (no cams or gears); a motor
//                         adds no member (it drives the pin it sits on);
//   2. structural rank  - a perfect matching of equations to unknowns in the Jacobian's pattern
//                         (augmenting paths); when there is none, the unmatched unknowns (or
//                         equations) and everything reachable from them by alternating paths is
//                         the under- (or over-) constrained part, reported by its joints.
//
// Mobility alone can be 1 while one part is over- and another under-constrained; step 2 finds that.

#include <string>
#include <vector>

#include "numlab/mechanisms/linkage/linkage_description.hpp"

namespace numlab::mechanisms {

class LinkageModel;

struct Mobility {
  int members = 0;          // n, the ground included
  int lower_pairs = 0;      // j1: pins and slider pairs
  int mobility = 0;         // M
  std::string formula() const;  // "3 (n - 1) - 2 j1 = 3 (4 - 1) - 2 (4) = 1"
};

Mobility gruebler_kutzbach(const LinkageDescription& description);

// The pivot-to-joint distance the crank keeps, from its link or body. Throws LinkageFileError when
// no link or body holds both (the reader checks this too).
double crank_radius(const LinkageDescription& description);
double crank_radius(const LinkageDescription& description, const DriverSpec& crank);
// The drivers: the first, then the second when the file has two.
std::vector<const DriverSpec*> drivers_of(const LinkageDescription& description);
// The distance a [[link]] or [[body]] holds between joints a and b, or -1 when none holds both.
double held_distance(const LinkageDescription& description, int a, int b);

// The structural problem of a model, or an empty string: "joints C, D: 3 equations for 4 unknowns".
struct StructuralProblem {
  std::string text;    // empty when the pattern has a perfect matching
  SourcePlace place;   // of the first item involved
};
StructuralProblem structural_problem(const LinkageModel& model);

// Throws LinkageFileError "FILE:LINE:COL: <structural problem>; mobility M (...), one driver needs 1"
// unless M equals the number of drivers (1, or 2 with a second driver) and the pattern has a perfect
// matching.
void require_one_degree_of_freedom(const LinkageModel& model);

}  // namespace numlab::mechanisms
