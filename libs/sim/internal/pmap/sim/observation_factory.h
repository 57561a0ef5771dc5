// Turns simulated measurements into MRPT objects, exactly as a robot's drivers
// would log them: 2D range scans, absolute odometry, odometry increments as
// CActionRobotMovement2D and externally stored camera images.
#pragma once

#include <mrpt/core/Clock.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationImage.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <string>

#include "pmap/sim/camera_model.h"
#include "pmap/sim/laser_sim.h"
#include "pmap/sim/pose.h"

namespace pmap::sim {

/// start_time_s (UNIX seconds) + offset_s, rounded to MRPT's 100 ns ticks.
mrpt::Clock::time_point simTimestamp(double start_time_s, double offset_s);

mrpt::obs::CObservation2DRangeScan::Ptr makeScanObservation(const LaserOptions& laser,
                                                            const SimulatedScan& scan,
                                                            mrpt::Clock::time_point stamp,
                                                            double sigma_m);

mrpt::obs::CObservationOdometry::Ptr makeOdometryObservation(const std::string& label,
                                                             const Pose2D& odometry_pose,
                                                             mrpt::Clock::time_point stamp);

/// A CActionCollection holding one CActionRobotMovement2D computed from the
/// odometry increment with MRPT's Gaussian motion model (parameters scaled to
/// the simulated drift).
mrpt::obs::CActionCollection::Ptr makeOdometryAction(const Pose2D& increment,
                                                     mrpt::Clock::time_point stamp);

/// An image observation whose pixels live in an external file `file_name`
/// (relative to the rawlog's "<name>_Images" directory). A non-zero
/// k.distortion is written as MRPT's plumb_bob model (cameraParams.dist =
/// k1 k2 p1 p2 k3), else the model is `none` with zero coefficients.
mrpt::obs::CObservationImage::Ptr makeImageObservation(const std::string& label,
                                                       const PinholeIntrinsics& k,
                                                       const Pose6D& camera_pose_on_robot,
                                                       const std::string& file_name,
                                                       mrpt::Clock::time_point stamp);

}  // namespace pmap::sim
