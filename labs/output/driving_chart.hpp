#pragma once
// `numlab mechanism FILE --sweep ... --chart FILE.svg|png`: the driving torque (or force) and the
// output's mechanical advantage against the driver over the sweep, drawn by gnuplot (chart.hpp: the
// chart whole or absent, its data and script beside it). One panel each; a file without [[load]]s
// charts the mechanical advantage alone and a file without an output the torque alone (the title
// says which); with neither there is nothing to chart (driving_chart_problem).

#include <optional>
#include <string>

#include "numlab/mechanisms/linkage/link_motion.hpp"
#include "numlab/mechanisms/linkage/linkage_sweep.hpp"
#include "output/chart.hpp"

namespace numlab::cli {

// Why --chart cannot be drawn for this model and output, in one line; empty when it can.
std::string driving_chart_problem(const mechanisms::LinkageModel& model, const std::optional<mechanisms::LinkageOutput>& output);

// The chart's data (driver, driver_torque|driver_force, statics, mechanical_advantage; a cell empty
// where the value is not finite: a singular pose, a toggle, a pose that did not assemble), its script,
// and the chart. The mechanical advantage's axis is clipped to 5 times its median size (the
// title says so) so that the poles at toggles do not flatten the curve.
void draw_driving_chart(const ChartFiles& files, const mechanisms::LinkageModel& model, const mechanisms::LinkageSweep& sweep,
                        const std::optional<mechanisms::LinkageOutput>& output);

}  // namespace numlab::cli
