#pragma once
// A planar linkage as its description file states it (docs/linkage-files.md): named joints, some
// fixed to the ground, binary links, rigid bodies, sliders, one driver and a reference pose. This is
// what the file says and nothing more; linkage_model.hpp derives the equations from it.
//
// Every item keeps the place in the file it came from, so that a problem found later (mobility,
// structure, a pose that does not assemble) can still be reported as FILE:LINE:COLUMN.

#include <Eigen/Core>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace numlab::mechanisms {

// Where something is in the description file; 0 when unknown.
struct SourcePlace {
  int line = 0;
  int column = 0;
};

struct JointSpec {
  std::string name;
  bool ground = false;       // fixed at `position`; otherwise moving, `position` is its rough place
  Eigen::Vector2d position;  // ground: exact; moving: a rough estimate at the reference pose
  SourcePlace place;
};

// A binary link: two joints at a fixed distance.
struct LinkSpec {
  int first = -1, second = -1;  // indices into LinkageDescription::joints
  double length = 0.0;
  SourcePlace place;
  std::string name{};           // `name`; empty: the default, its joints joined by '-' (link_name())
  SourcePlace name_place{};
};

// A rigid body with three or more joints, given in the body's own (local) coordinates.
struct BodySpec {
  std::string name;
  std::vector<int> joints;               // indices into LinkageDescription::joints
  std::vector<Eigen::Vector2d> local;    // one local position per joint, no two coinciding
  SourcePlace place;
  bool collinear = false;                // every local point on one line: a bar (drawn as one), still rigid
};

// A joint held on a straight line: fixed to the ground (through `through`, at `angle_deg` from +x),
// or carried by a moving link or body (`line`: the line from joint line_from to joint line_to of one
// link or body, the slot `offset` to its left). Exactly one of the two.
struct SliderSpec {
  int joint = -1;
  Eigen::Vector2d through = Eigen::Vector2d::Zero();
  double angle_deg = 0.0;
  SourcePlace place;
  SourcePlace angle_place{};  // of `angle`; the slider's place when the file leaves it out
  int line_from = -1, line_to = -1;  // `line = ["B", "C"]`: the carrying body's joints, or -1 (a fixed line)
  double offset = 0.0;               // the slot's signed distance to the left of B -> C (length units)
  bool on_link() const { return line_from >= 0; }
};

enum class DriverKind { crank, slider, actuator, motor };

// The one input. A crank turns `joint` about the ground joint `pivot` (the angle of pivot -> joint
// from +x, in degrees); a slider driver moves the slider's joint along its line (the travel from
// the line's `through` point, in length units); an actuator sets the distance |from - joint| (length
// units); a motor sets the angle from pivot -> from to pivot -> joint (degrees, counter-clockwise),
// two links or bodies turning about their shared joint `pivot`. Self-contained, so that a mechanism
// of mobility 2 can later hold a list of them.
struct DriverSpec {
  DriverKind kind = DriverKind::crank;
  int pivot = -1;      // crank: a ground joint; motor: the joint the two links share
  int joint = -1;      // the driven joint (crank: on a link or body with the pivot; slider: a slider's joint;
                       // actuator: its second joint; motor: on the second link or body)
  int slider = -1;     // slider driver: index into LinkageDescription::sliders
  double reference = 0.0;  // the driver's value at the reference pose (degrees or length)
  SourcePlace place;
  SourcePlace reference_place{};  // of `angle` (crank, motor), `travel` (slider) or `length` (actuator)
  int from = -1;       // actuator: its first joint; motor: the joint on the first link or body (last, so
                       // that {kind, pivot, joint, slider, reference, place} still initialises a crank)
  bool angle() const { return kind == DriverKind::crank || kind == DriverKind::motor; }  // degrees, else length
};

// A load on the mechanism ([[load]], docs/linkage-files.md "Loads and the driving torque"): a force
// at a joint (N), a torque on a link or body (N times the file's length unit, counter-clockwise
// positive), or a mass at a joint (kg) that gravity pulls down -y with m g (N, g in m/s^2).
enum class LoadKind { force, torque, mass };

struct LoadSpec {
  LoadKind kind = LoadKind::force;
  int joint = -1;  // force, mass: index into LinkageDescription::joints
  int line = -1;   // torque: index into link_lines() (links, then bodies, in file order)
  Eigen::Vector2d force = Eigen::Vector2d::Zero();  // force: [Fx, Fy]
  double torque = 0.0;                              // torque
  double mass = 0.0;                                // mass
  SourcePlace place;
};

inline constexpr double standard_gravity = 9.80665;  // m/s^2, the default of [linkage] gravity

struct LinkageDescription {
  std::string file;    // as given, for messages
  std::string name;    // [linkage] name
  std::string title;   // [linkage] title (may be empty)
  std::string output;  // [linkage] output: a link's or body's name, or a slider's joint (may be empty)
  SourcePlace output_place{};
  std::vector<JointSpec> joints;  // in the order the file lists them: ground first, then moving
  std::vector<LinkSpec> links;
  std::vector<BodySpec> bodies;
  std::vector<SliderSpec> sliders;
  DriverSpec driver;
  // A second input ([[driver]] twice: mobility 2, a five-bar). A sweep moves `driver` with this one
  // held at its reference (or at each row's value of a --drivers path). A crank, slider or actuator.
  std::optional<DriverSpec> second_driver;
  std::vector<LoadSpec> loads;              // [[load]], in file order
  double gravity = standard_gravity;        // [linkage] gravity, m/s^2 along -y (masses only)
  std::vector<int> trace;                   // [linkage] trace: moving joints whose paths --svg highlights

  // The index of the joint called `name`, or -1.
  int joint_index(std::string_view name) const;
};

// A description that cannot be used: what() is one line, "FILE:LINE:COLUMN: problem" (or
// "FILE: problem" when the problem has no single place). The command line prints it and exits 2.
class LinkageFileError : public std::invalid_argument {
 public:
  LinkageFileError(const std::string& file, SourcePlace place, const std::string& problem);
  const std::string& problem() const { return problem_; }
  SourcePlace place() const { return place_; }

 private:
  std::string problem_;
  SourcePlace place_;
};

// Reads a description from TOML text (`file` names it in messages). Checks everything that can be
// checked from the file alone: TOML syntax, the sections and keys, unknown and duplicate joint names,
// a link from a joint to itself, lengths (positive and finite), numbers finite, bodies (three or
// more distinct joints, no two local points coinciding), sliders (on a fixed line or on the line of
// two joints of one link or body), the driver (a crank on a ground pivot, its joint on a link or body
// with it; a slider driver; an actuator between joints no link holds; a motor between two links or
// bodies at their shared joint). Throws LinkageFileError.
LinkageDescription parse_linkage_description(std::string_view toml_text, const std::string& file);

// Reads the file (at most linalg::max_input_file_bytes) and parses it. Throws LinkageFileError.
LinkageDescription read_linkage_description(const std::string& path);

}  // namespace numlab::mechanisms
