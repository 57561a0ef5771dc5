// A keyframe of the pose graph (loop_closure.h): a pose-laser scan kept
// every keyframe_distance_m / keyframe_angle_deg of front-end motion.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "pmap/poses/odometry_model.h"
#include "pmap/poses/pose_graph.h"

namespace pmap::poses {

struct Keyframe {
  double t = 0;                            ///< s
  Pose2 front;                             ///< the front end's pose (its own frame)
  double path_m = 0;                       ///< front-end path length up to here
  std::vector<Eigen::Vector2d> points;     ///< the pose laser's points, robot frame
  std::optional<OdometrySample> odometry;  ///< the wheel odometry there, if the log has it
};

}  // namespace pmap::poses
