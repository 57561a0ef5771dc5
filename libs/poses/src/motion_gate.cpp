#include "pmap/poses/motion_gate.h"

#include <mrpt/core/bits_math.h>
#include <mrpt/math/wrap2pi.h>
#include <mrpt/poses/CPose3D.h>

#include <cmath>

namespace pmap::poses {
namespace {

using mrpt::math::TPose3D;
using mrpt::poses::CPose3D;

double dtOrZero(double dt_s) {
  return std::isfinite(dt_s) && dt_s > 0.0 ? dt_s : 0.0;
}

TPose3D compose(const TPose3D& a, const TPose3D& b) {
  return (CPose3D(a) + CPose3D(b)).asTPose();
}

TPose3D inverse(const TPose3D& a) {
  CPose3D p(a);
  p.inverse();
  return p.asTPose();
}

}  // namespace

bool MotionLimits::validate(std::string* why) const {
  const struct {
    const char* name;
    double value;
  } positive[] = {{"max_speed_mps", max_speed_mps},
                  {"max_turn_rate_dps", max_turn_rate_dps},
                  {"max_step_m", max_step_m},
                  {"max_step_deg", max_step_deg},
                  {"max_coordinate_m", max_coordinate_m}};
  for (const auto& p : positive) {
    if (!(p.value > 0.0) || !std::isfinite(p.value)) {
      *why = std::string(p.name) + " must be a finite number > 0";
      return false;
    }
  }
  if (reset_after < 0 || reset_after > 1000) {
    *why = "reset_after must be in [0, 1000] (0: never re-anchor)";
    return false;
  }
  return true;
}

std::size_t* MotionGate::implausiblePose(const TPose3D& p) {
  const double v[] = {p.x, p.y, p.z, p.yaw, p.pitch, p.roll};
  for (const double x : v) {
    if (!std::isfinite(x)) {
      return &stats_.non_finite;
    }
  }
  const double m = limits_.max_coordinate_m;
  if (std::fabs(p.x) > m || std::fabs(p.y) > m || std::fabs(p.z) > m) {
    return &stats_.too_far;
  }
  return nullptr;
}

bool MotionGate::plausibleStep(double dt_s, const TPose3D& from, const TPose3D& to) const {
  const double dt = dtOrZero(dt_s);
  const double moved = std::hypot(to.x - from.x, to.y - from.y, to.z - from.z);
  const double turned = std::fabs(mrpt::math::wrapToPi(to.yaw - from.yaw));
  return moved <= limits_.max_step_m + limits_.max_speed_mps * dt &&
         turned <= mrpt::DEG2RAD(limits_.max_step_deg + limits_.max_turn_rate_dps * dt);
}

std::optional<TPose3D> MotionGate::absolute(double t_s, const TPose3D& reading) {
  if (std::size_t* counter = implausiblePose(reading)) {
    ++*counter;
    return std::nullopt;
  }
  const Reading r{t_s, reading};
  if (last_raw_ && !plausibleStep(t_s - last_raw_->t, last_raw_->pose, reading)) {
    return rejectStep(r);
  }
  rejected_.clear();
  last_raw_ = r;
  return compose(offset_, reading);
}

// A reading too far from the last accepted one: dropped, unless it is the
// reset_after-th of a run of rejected readings that agree with each other.
std::optional<TPose3D> MotionGate::rejectStep(const Reading& r) {
  if (!rejected_.empty() &&
      !plausibleStep(r.t - rejected_.back().t, rejected_.back().pose, r.pose)) {
    rejected_.clear();
  }
  rejected_.push_back(r);
  if (limits_.reset_after == 0 ||
      rejected_.size() < static_cast<std::size_t>(limits_.reset_after)) {
    ++stats_.too_fast;
    return std::nullopt;
  }
  // The run starts where the robot was: offset' (+) first = offset (+) last.
  offset_ = compose(compose(offset_, last_raw_->pose), inverse(rejected_.front().pose));
  ++stats_.resets;
  rejected_.clear();
  last_raw_ = r;
  return compose(offset_, r.pose);
}

bool MotionGate::increment(double dt_s, const TPose3D& step) {
  if (std::size_t* counter = implausiblePose(step)) {
    ++*counter;
    return false;
  }
  if (!plausibleStep(dt_s, TPose3D(0, 0, 0, 0, 0, 0), step)) {
    ++stats_.too_fast;
    return false;
  }
  return true;
}

std::string MotionGate::summary(const std::string& what) const {
  if (stats_.dropped() == 0 && stats_.resets == 0) {
    return {};
  }
  std::string s = "implausible motion: " + std::to_string(stats_.dropped()) + " " + what +
                  " dropped (" + std::to_string(stats_.non_finite) + " non-finite, " +
                  std::to_string(stats_.too_far) + " beyond max_coordinate_m = " +
                  std::to_string(static_cast<long long>(limits_.max_coordinate_m)) + " m, " +
                  std::to_string(stats_.too_fast) + " steps beyond max_speed_mps / " +
                  "max_turn_rate_dps / max_step_m)";
  if (stats_.resets > 0) {
    s += ", " + std::to_string(stats_.resets) + " odometry reset(s) re-anchored";
  }
  return s + "; limits in [Poses] (doc/poses.md)";
}

}  // namespace pmap::poses
