#pragma once
// The sentences of the lab `basins`, built from the numbers printed beside them (tests/basins
// checks each against the lab's saved tables).

#include <string>

namespace numlab::basins {

// "41.2%" of count out of total, one decimal.
std::string percent(int count, int total);

// Where the seed's estimates sit on the slice and which branch Newton reaches from there.
std::string seed_position_sentence(double distance, bool reaches_seed_mode, const std::string& seed_label);

// How far a start may stray: the nearest start converging to another branch, and the nearest that
// fails, both measured from the solution in the slice (radians); infinity = none on the slice.
std::string stray_sentence(const std::string& method, double to_other_mode, double to_failure, double grid_step);

// What damping changes: the share of the slice that reaches the seed's branch, plain against damped.
std::string damping_sentence(int plain_home, int damped_home, int total, int plain_failed, int damped_failed);

// The fractal: how many starts reach each root, and how many fail.
std::string fractal_sentence(int root1, int root2, int root3, int failed, int total);

// The four-bar: the two modes' shares, and the failing starts (singular ones lie on the toggle lines).
std::string four_bar_sentence(int mode_plus, int mode_minus, int singular, int failed, int total);

}  // namespace numlab::basins
