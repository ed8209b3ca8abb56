#pragma once
// Lab `basins`: from which starting guesses Newton reaches which assembly mode.

#include "lessons/lab.hpp"

namespace numlab::cli {

// The grid side of the lab's maps (fractal and four-bar one more, so that the centre is a grid point).
inline constexpr int basins_lab_grid = 200;

int run_basins_lab(LabSession& session);

}  // namespace numlab::cli
