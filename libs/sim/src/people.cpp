#include "pmap/sim/people.h"

#include <algorithm>
#include <cmath>

namespace pmap::sim {
namespace {

PathSpec walkingPath(const PersonSpec& spec) {
  PathSpec p;
  p.waypoints = spec.waypoints;
  p.speed_m_s = spec.speed_m_s;
  p.corner_radius_m = spec.corner_radius_m;
  p.max_yaw_rate_deg_s = 360.0;  // people turn on the spot; the radius rounds the corners
  p.robot_radius_m = spec.radius_m;
  return p;
}

}  // namespace

WalkingPerson::WalkingPerson(const PersonSpec& spec, const std::string& file)
    : spec_(spec), walk_(walkingPath(spec), file + ": " + spec.where) {}

VerticalCylinder WalkingPerson::at(double t_s) const {
  const double period = 2.0 * walk_.duration_s();
  const double walked = std::max(0.0, t_s - spec_.start_s);
  const double phase = period > 0.0 ? std::fmod(walked, period) : 0.0;
  const double along = phase <= 0.5 * period ? phase : period - phase;  // there, then back
  const Pose2D p = walk_.poseAtTime(along);
  return VerticalCylinder{Eigen::Vector2d(p.x, p.y), spec_.radius_m, 0.0, spec_.height_m};
}

PeopleAt::PeopleAt(const std::vector<WalkingPerson>& people, double t_s) {
  for (const WalkingPerson& p : people) {
    cylinders_.push_back(p.at(t_s));
    ids_.push_back(p.id);
  }
}

std::optional<PeopleAt::Hit> PeopleAt::cast(const Eigen::Vector3d& origin,
                                            const Eigen::Vector3d& dir, double t_min,
                                            double t_max) const {
  std::optional<Hit> best;
  for (std::size_t i = 0; i < cylinders_.size(); ++i) {
    const double limit = best ? best->hit.t : t_max;
    if (const auto h = intersectCylinder(cylinders_[i], origin, dir, t_min, limit)) {
      if (!best || h->t < best->hit.t) {
        best = Hit{ids_[i], *h};
      }
    }
  }
  return best;
}

}  // namespace pmap::sim
