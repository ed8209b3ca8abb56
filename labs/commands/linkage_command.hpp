#pragma once
// `numlab mechanism FILE|MODEL ...` for a linkage described in a file (docs/linkage-files.md): the
// derived model (--explain), then positions, velocities, accelerations, limits and scenes over a
// crank (or slider) sweep with any solver. The built-in jansen, jansen10 and mustang are not here
// (mechanism_command.cpp).

#include <optional>
#include <string>
#include <vector>

#include "commands/common_options.hpp"

namespace numlab::cli {

struct LinkageRun {
  std::string file;                // the description file
  std::optional<double> driver;    // --crank: one value (degrees, or travel for a slider driver)
  std::string sweep;               // --sweep START:STOP:STEP (same units)
  std::string drivers;             // --drivers PATH.csv: both drivers along a path (a file with two drivers)
  std::string solver = "full";
  std::string linear = "gepp";
  bool linear_given = false;
  bool explain = false;            // print the derived model and stop
  bool check_jacobian = false;     // compare J with finite differences at every solved pose
  bool arrows = false;             // --svg draws velocity arrows
  bool strict = false;             // --strict: an authoring warning is bad input (exit 2)
  bool switch_at_crossing = false; // --at-crossing switch: take the other branch where two cross
  bool analyse = false;            // --analyse: the four-bar or slider-crank analysis, and stop
  std::string output;              // --output: a link, body or slider joint (else the file's `output`)
  std::optional<double> speed_rad_s;  // --speed: the crank's speed, rad/s
  CommonOptions common;
  std::string svg, animate;        // already placed inside --out
  std::string html;                // --html: the linkage page (inside --out)
  std::string name;                // the name given on the command line, for the page
  std::optional<double> draw_at;   // --draw-at: the pose --svg draws, a driver value of the sweep
  std::vector<std::string> paths;  // --path: joints whose paths the scenes highlight (else the file's trace)
  std::string chart;               // --chart: the driving torque and mechanical advantage (inside --out)
};

// The description file a mechanism name stands for: NAME as a path when such a file exists, else
// the shipped model NAME (NAME.toml in the models folder). Empty when neither exists.
std::string linkage_file_for(const std::string& name);

// Runs it; returns the exit code. Bad input throws std::invalid_argument (LinkageFileError included).
int run_linkage(const LinkageRun& run);

}  // namespace numlab::cli
