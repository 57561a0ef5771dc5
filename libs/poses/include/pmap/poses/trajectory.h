// A robot trajectory: poses sorted by strictly increasing timestamp, with
// interpolation (linear in position, spherical-linear in orientation).
#pragma once

#include <mrpt/math/TPose3D.h>

#include <optional>
#include <vector>

namespace pmap::poses {

struct TimedPose {
  double t = 0;  ///< seconds (mrpt::Clock::toDouble)
  mrpt::math::TPose3D pose;
};

class Trajectory {
 public:
  /// Appends a pose. A pose at the same timestamp as the last replaces it;
  /// an older timestamp is refused (returns false).
  bool append(double t, const mrpt::math::TPose3D& pose);

  bool empty() const { return poses_.empty(); }
  std::size_t size() const { return poses_.size(); }
  const std::vector<TimedPose>& poses() const { return poses_; }
  double firstTime() const { return poses_.front().t; }
  double lastTime() const { return poses_.back().t; }

  /// The pose at time t: interpolated between the two poses around it, exact
  /// at a sample. Empty outside [firstTime, lastTime] or when the two poses
  /// around t are more than `max_gap_s` apart.
  std::optional<mrpt::math::TPose3D> at(double t, double max_gap_s) const;

 private:
  std::vector<TimedPose> poses_;
};

/// Interpolates between two poses, s in [0, 1].
mrpt::math::TPose3D interpolatePose(const mrpt::math::TPose3D& a, const mrpt::math::TPose3D& b,
                                    double s);

}  // namespace pmap::poses
