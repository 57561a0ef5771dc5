#include "pmap/sim/world_spec.h"

#include <cmath>

namespace pmap::sim {

bool PathSpec::validate(std::string* why) const {
  auto fail = [why](const std::string& m) {
    if (why != nullptr) {
      *why = m;
    }
    return false;
  };
  if (waypoints.size() < 2) {
    return fail("waypoints needs at least 2 points");
  }
  if (!(speed_m_s > 0.0 && speed_m_s <= 10.0)) {
    return fail("speed_m_s must be in (0, 10]");
  }
  if (!(corner_radius_m >= 0.0 && corner_radius_m <= 100.0)) {
    return fail("corner_radius_m must be in [0, 100]");
  }
  if (!(max_yaw_rate_deg_s > 0.0 && max_yaw_rate_deg_s <= 360.0)) {
    return fail("max_yaw_rate_deg_s must be in (0, 360]");
  }
  if (!(robot_radius_m >= 0.0 && robot_radius_m <= 2.0)) {
    return fail("robot_radius_m must be in [0, 2]");
  }
  return true;
}

const std::vector<std::string>& freeRectangleKinds() {
  static const std::vector<std::string> kinds = {
      "wall",         "door",     "ceiling", "floor",   "jamb",  "room_wall", "room_floor",
      "room_ceiling", "bulkhead", "panel",   "cabinet", "glass", "other"};
  return kinds;
}

const std::vector<std::string>& clutterKinds() {
  static const std::vector<std::string> kinds = {"bin",     "column", "pillar", "radiator",
                                                 "cabinet", "shelf",  "desk",   "lamp",
                                                 "duct",    "beam",   "pipe"};
  return kinds;
}

}  // namespace pmap::sim
