// libFuzzer target: numlab::mechanisms::parse_linkage_description, the reader of linkage description
// files (TOML, read by toml++ compiled here too, so its parser is instrumented as well).

#include <cmath>

#include "fuzz_target.hpp"
#include "numlab/mechanisms/linkage/linkage_description.hpp"

namespace {

using namespace numlab::mechanisms;

bool valid_joint_name(const std::string& name) {
  if (name.empty() || name.size() > 32) return false;
  for (const char c : name) {
    const bool letter = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
    if (!letter && !(c >= '0' && c <= '9') && c != '_') return false;
  }
  return true;
}

bool finite(const Eigen::Vector2d& p) { return std::isfinite(p.x()) && std::isfinite(p.y()); }

// The promises of a description that was accepted (linkage_description.hpp).
void check_description(const LinkageDescription& d) {
  using numlab::fuzz::require;
  const int joints = static_cast<int>(d.joints.size());
  const auto joint = [&](int index) { return index >= 0 && index < joints; };
  require(!d.name.empty(), "a linkage name");
  require(joints <= 1000, "at most 1000 joints");
  bool moving = false, ground_done = false;
  for (int i = 0; i < joints; ++i) {
    const JointSpec& j = d.joints[static_cast<std::size_t>(i)];
    require(valid_joint_name(j.name), "joint names of letters, digits and '_'");
    require(d.joint_index(j.name) == i, "joint names unique");
    require(finite(j.position), "joint positions finite");
    require(!(j.ground && ground_done), "ground joints first");
    ground_done = ground_done || !j.ground;
    moving = moving || !j.ground;
  }
  require(moving, "a moving joint");
  for (const LinkSpec& link : d.links) {
    require(joint(link.first) && joint(link.second) && link.first != link.second, "a link's joints in range, two");
    require(std::isfinite(link.length) && link.length > 0.0, "a link's length positive and finite");
  }
  for (const BodySpec& body : d.bodies) {
    require(body.joints.size() >= 3 && body.local.size() == body.joints.size(), "a body of 3 or more joints");
    for (std::size_t k = 0; k < body.joints.size(); ++k) {
      require(joint(body.joints[k]) && finite(body.local[k]), "a body's joints in range, local points finite");
    }
  }
  for (const SliderSpec& slider : d.sliders) {
    require(joint(slider.joint) && !d.joints[static_cast<std::size_t>(slider.joint)].ground, "a slider on a moving joint");
    require(finite(slider.through) && std::isfinite(slider.angle_deg), "a slider's line finite");
  }
  const auto ground = [&](int index) { return d.joints[static_cast<std::size_t>(index)].ground; };
  const auto check_driver = [&](const DriverSpec& driver) {
    require(std::isfinite(driver.reference), "the driver's value finite");
    require(joint(driver.joint), "the driven joint in range");
    switch (driver.kind) {
      case DriverKind::crank:
        require(!ground(driver.joint), "a crank's joint moves");
        require(joint(driver.pivot) && ground(driver.pivot), "a crank on a ground pivot");
        break;
      case DriverKind::slider:
        require(!ground(driver.joint), "a slider driver's joint moves");
        require(driver.slider >= 0 && driver.slider < static_cast<int>(d.sliders.size()) &&
                    d.sliders[static_cast<std::size_t>(driver.slider)].joint == driver.joint,
                "a slider driver on its slider's joint");
        break;
      case DriverKind::actuator:
        require(joint(driver.from) && driver.from != driver.joint, "an actuator between two joints");
        require(!(ground(driver.from) && ground(driver.joint)), "an actuator not between two ground joints");
        require(driver.reference > 0.0, "an actuator's length positive");
        break;
      case DriverKind::motor:
        require(joint(driver.pivot) && joint(driver.from), "a motor's joints in range");
        require(driver.from != driver.joint && driver.pivot != driver.from && driver.pivot != driver.joint,
                "a motor's three joints different");
        break;
    }
  };
  check_driver(d.driver);
  if (d.second_driver) {
    check_driver(*d.second_driver);
    require(d.second_driver->kind != DriverKind::motor, "a held second driver is not a motor");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return numlab::fuzz::run_parser(
      [&] { check_description(parse_linkage_description(numlab::fuzz::as_text(data, size), "fuzz.toml")); });
}
