#include "output/driver_units.hpp"

namespace numlab::cli {

std::string velocity_per(mechanisms::DriverKind kind) {
  switch (kind) {
    case mechanisms::DriverKind::crank: return "radian of crank";
    case mechanisms::DriverKind::motor: return "radian of motor";
    case mechanisms::DriverKind::slider: return "unit of slider travel";
    case mechanisms::DriverKind::actuator: return "unit of actuator length";
  }
  return "unit of the driver";
}

}  // namespace numlab::cli
