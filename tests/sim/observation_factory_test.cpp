#include "pmap/sim/observation_factory.h"

#include <gtest/gtest.h>

#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/poses/CPosePDF.h>

namespace pmap::sim {
namespace {

TEST(ObservationFactory, TimestampsAreExactTicks) {
  const auto t0 = simTimestamp(1767225600.0, 0.0);
  EXPECT_EQ(mrpt::Clock::toDouble(t0), 1767225600.0);
  for (int k = 0; k < 50; ++k) {
    const auto t = simTimestamp(1767225600.0, k / 5.0 + 0.1);
    EXPECT_EQ((t - t0).count(), static_cast<mrpt::Clock::rep>(k) * 2000000 + 1000000);
  }
}

TEST(ObservationFactory, ScanObservationFields) {
  const SensorOptions sensors;
  SimulatedScan scan;
  scan.ranges_m.assign(181, 2.0f);
  scan.valid.assign(181, 1);
  scan.valid[7] = 0;
  scan.ranges_m[7] = 30.0f;
  const auto obs =
      makeScanObservation(sensors.laser_v, scan, simTimestamp(1767225600.0, 0.1), 0.02);
  EXPECT_EQ(obs->sensorLabel, "LASER_V");
  EXPECT_EQ(obs->getScanSize(), 181u);
  EXPECT_NEAR(obs->aperture, M_PI, 1e-6);
  EXPECT_TRUE(obs->rightToLeft);
  EXPECT_EQ(obs->maxRange, 30.0f);
  EXPECT_FALSE(obs->getScanRangeValidity(7));
  EXPECT_TRUE(obs->getScanRangeValidity(8));
  EXPECT_NEAR(obs->sensorPose.z(), 0.3, 1e-12);
  EXPECT_NEAR(obs->sensorPose.pitch(), -M_PI / 2, 1e-12);
  EXPECT_FALSE(obs->isPlanarScan());
  const auto h = makeScanObservation(sensors.laser_h, scan, simTimestamp(1767225600.0, 0.0), 0.02);
  EXPECT_TRUE(h->isPlanarScan());
  EXPECT_NEAR(h->sensorPose.x(), 0.2, 1e-12);
}

TEST(ObservationFactory, OdometryAndAction) {
  const auto odo =
      makeOdometryObservation("ODOMETRY", Pose2D{1.0, 2.0, 0.3}, simTimestamp(1767225600.0, 0.0));
  EXPECT_EQ(odo->odometry.x(), 1.0);
  EXPECT_NEAR(odo->odometry.phi(), 0.3, 1e-15);
  const auto actions = makeOdometryAction(Pose2D{0.08, 0.001, 0.002}, simTimestamp(0.0, 0.0));
  ASSERT_EQ(actions->size(), 1u);
  const auto move = actions->getBestMovementEstimation();
  ASSERT_TRUE(move);
  const mrpt::poses::CPose2D mean = move->poseChange->getMeanVal();
  EXPECT_NEAR(mean.x(), 0.08, 1e-12);
  EXPECT_NEAR(mean.phi(), 0.002, 1e-12);
  EXPECT_NEAR(move->rawOdometryIncrementReading.x(), 0.08, 1e-12);
}

TEST(ObservationFactory, ImageIsExternallyStored) {
  const auto k = PinholeIntrinsics::fromFov(640, 480, M_PI / 2);
  const auto obs = makeImageObservation("CAMERA_LEFT", k, Pose6D{0, 0.05, 1.0, 0, 0, -M_PI / 2},
                                        "CAMERA_LEFT_000003.jpg", simTimestamp(0.0, 0.05));
  EXPECT_TRUE(obs->image.isExternallyStored());
  EXPECT_EQ(obs->image.getExternalStorageFile(), "CAMERA_LEFT_000003.jpg");
  EXPECT_EQ(obs->cameraParams.ncols, 640u);
  EXPECT_NEAR(obs->cameraParams.fx(), 320.0, 1e-9);
  EXPECT_NEAR(obs->cameraParams.cx(), 319.5, 1e-12);
  EXPECT_NEAR(obs->cameraPose.roll(), -M_PI / 2, 1e-12);
  EXPECT_EQ(obs->cameraParams.distortion, mrpt::img::DistortionModel::none);
  EXPECT_EQ(obs->cameraParams.k1(), 0.0);
}

}  // namespace
}  // namespace pmap::sim
