#pragma once
// The Jansen foot's path over one crank cycle (closed form, 1 degree apart), for the fitting lab
// and `numlab fit --foot-path upper|lower`.

#include <string>

#include "numlab/fitting/path_arcs.hpp"

namespace numlab::cli {

// Foot positions at crank angles 0, 1, ..., 359 degrees, split into arcs at the extreme x.
fitting::SplitPath jansen_foot_arcs();

// "upper" or "lower"; throws std::invalid_argument for anything else.
fitting::PathArc jansen_foot_arc(const std::string& which);

}  // namespace numlab::cli
