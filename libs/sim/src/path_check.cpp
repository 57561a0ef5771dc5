#include "pmap/sim/path_check.h"

#include <cmath>
#include <cstdio>

#include "pmap/common/error.h"

namespace pmap::sim {
namespace {

constexpr double kStep_m = 0.05;
constexpr int kDirections = 16;
constexpr double kHeights_m[] = {0.1, 0.4, 1.0};

std::string objectName(const RayCaster& caster, const SceneHit& hit) {
  const World& w = caster.world();
  const std::string kind = hit.type == ObjectType::kSurface
                               ? w.surfaces[static_cast<std::size_t>(hit.index)].kind
                               : w.clutter[static_cast<std::size_t>(hit.index)].kind;
  return kind + " " + std::to_string(hit.id);
}

[[noreturn]] void fail(const std::string& file, const std::string& what, const Pose2D& at) {
  char where[64];
  std::snprintf(where, sizeof(where), " near (%.2f, %.2f)", at.x, at.y);
  throw ConfigError(file + ": path: " + what + where);
}

}  // namespace

void checkPathClearance(const RayCaster& caster, const Trajectory& trajectory,
                        double robot_radius_m, const std::string& file, const std::string& who,
                        const std::string& moves) {
  const int steps = static_cast<int>(std::ceil(trajectory.length_m() / kStep_m));
  for (int k = 0; k <= steps; ++k) {
    const Pose2D a = trajectory.poseAtDistance(k * kStep_m);
    const Pose2D b = trajectory.poseAtDistance((k + 1) * kStep_m);
    const Eigen::Vector3d ground(a.x, a.y, 0.0);
    const std::vector<int> near =
        caster.selectNearPoint(ground, robot_radius_m + 2.0 * kStep_m + 1.0);
    for (const double z : kHeights_m) {
      const Eigen::Vector3d o(a.x, a.y, z);
      const Eigen::Vector3d step(b.x - a.x, b.y - a.y, 0.0);
      if (step.norm() > 1e-12) {
        if (const auto hit = caster.cast(o, step, 1.0, &near)) {
          fail(file, who + " " + moves + " through " + objectName(caster, *hit), a);
        }
      }
      for (int d = 0; d < kDirections && robot_radius_m > 0.0; ++d) {
        const double angle = 2.0 * M_PI * d / kDirections;
        const Eigen::Vector3d dir(std::cos(angle), std::sin(angle), 0.0);
        if (const auto hit = caster.cast(o, dir, robot_radius_m, &near)) {
          fail(file,
               who + " (radius " + std::to_string(robot_radius_m) + " m) touches " +
                   objectName(caster, *hit),
               a);
        }
      }
    }
  }
}

}  // namespace pmap::sim
