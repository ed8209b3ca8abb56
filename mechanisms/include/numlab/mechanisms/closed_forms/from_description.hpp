#pragma once
// The closed forms' numbers read from the shipped files (mechanisms/models/), so that the tests and
// the bench hold each file against the closed form of the very mechanism it describes: ground
// joints' positions, link lengths, a body's local points, by the joint names the files use. Throws
// std::invalid_argument when a description lacks a joint or link they need.

#include "numlab/mechanisms/closed_forms/hydraulic_boom.hpp"
#include "numlab/mechanisms/closed_forms/inverted_slider_crank.hpp"
#include "numlab/mechanisms/closed_forms/watt_linkage.hpp"
#include "numlab/mechanisms/closed_forms/whitworth.hpp"
#include "numlab/mechanisms/linkage/linkage_description.hpp"

namespace numlab::mechanisms::closed_forms {

// inverted-slider-crank.toml: ground O and B, links O-A and B-C.
InvertedSliderCrank inverted_slider_crank_of(const LinkageDescription& description);
// whitworth.toml: ground O2 and O4, links O2-A, O4-B and B-C, C on a ground slider (its line y = h).
Whitworth whitworth_of(const LinkageDescription& description);
// hydraulic-boom.toml: ground O and P, the body O-B-T (its local points), B's side of O -> P from its
// rough position.
HydraulicBoom hydraulic_boom_of(const LinkageDescription& description);
// watt-straight-line.toml: ground O1 and O2, links O1-B and O2-C, the body B-M-C (M's fraction of
// B -> C from its local points), C's side of B -> O2 from the rough positions.
WattLinkage watt_linkage_of(const LinkageDescription& description);

}  // namespace numlab::mechanisms::closed_forms
