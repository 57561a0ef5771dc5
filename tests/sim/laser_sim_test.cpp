#include "pmap/sim/laser_sim.h"

#include <gtest/gtest.h>

#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose3D.h>

#include "pmap/sim/observation_factory.h"
#include "pmap/sim/world_builder.h"
#include "pmap/sim/world_loader.h"

namespace pmap::sim {
namespace {

World straightCorridor() {
  return buildWorld(parseWorldText(
      R"({"name": "c", "corridors": [{"centreline": [[0, 0], [20, 0]], "width_m": 2.0,
          "height_m": 2.5}], "path": {"waypoints": [[1, 0], [19, 0]]}})",
      "w.json"));
}

/// The guard that our rotations agree with MRPT's: direction of beam i from
/// (robot pose (+) sensorPose) applied to the sensor-frame point, by MRPT.
TEST(LaserSim, BeamDirectionsMatchMrptCPose3D) {
  const SensorOptions sensors;
  const Pose2D robots[] = {{0, 0, 0}, {3.0, -2.0, 0.7}, {-1.0, 4.0, -2.5}};
  for (const LaserOptions& laser : {sensors.laser_h, sensors.laser_v}) {
    const Pose6D m = laserMountPose(laser);
    const mrpt::poses::CPose3D mount(m.x, m.y, m.z, m.yaw, m.pitch, m.roll);
    for (const Pose2D& r : robots) {
      const mrpt::poses::CPose3D sensor = mrpt::poses::CPose3D(r.x, r.y, 0, r.yaw, 0, 0) + mount;
      for (const int i : {0, 1, 45, 90, 135, 180}) {
        const double a = beamAngle(laser, i);
        double gx, gy, gz;
        sensor.composePoint(std::cos(a), std::sin(a), 0.0, gx, gy, gz);
        const Eigen::Vector3d theirs(gx - sensor.x(), gy - sensor.y(), gz - sensor.z());
        const Eigen::Vector3d ours = beamDirectionInWorld(r, laser, i);
        EXPECT_TRUE(ours.isApprox(theirs, 1e-12)) << laser.label << " beam " << i;
        EXPECT_TRUE(laserToWorld(r, laser).translation.isApprox(
            Eigen::Vector3d(sensor.x(), sensor.y(), sensor.z()), 1e-12));
      }
    }
  }
}

TEST(LaserSim, BeamAnglesMatchMrptScanAngles) {
  const SensorOptions sensors;
  SimulatedScan scan;
  scan.ranges_m.assign(181, 1.0f);
  scan.valid.assign(181, 1);
  const auto obs = makeScanObservation(sensors.laser_v, scan, simTimestamp(0.0, 0.0), 0.02);
  for (int i = 0; i < 181; ++i) {
    EXPECT_NEAR(obs->getScanAngle(static_cast<std::size_t>(i)), beamAngle(sensors.laser_v, i),
                1e-6);
  }
}

TEST(LaserSim, VerticalLaserGeometry) {
  const SensorOptions sensors;
  const Pose2D robot{5.0, 0.0, 0.0};
  // Beam 0 points right (robot -y), the middle one up, the last one left.
  EXPECT_TRUE(beamDirectionInWorld(robot, sensors.laser_v, 0).isApprox(-Eigen::Vector3d::UnitY()));
  EXPECT_TRUE(beamDirectionInWorld(robot, sensors.laser_v, 90).isApprox(Eigen::Vector3d::UnitZ()));
  EXPECT_TRUE(beamDirectionInWorld(robot, sensors.laser_v, 180).isApprox(Eigen::Vector3d::UnitY()));
}

TEST(LaserSim, StraightUpBeamHitsTheCeilingAtHeightMinusMount) {
  const World w = straightCorridor();
  const RayCaster caster(w);
  Rng rng(1);
  const SimulatedScan s = simulateScan(caster, Pose2D{5.0, 0.3, 0.4}, w.sensors.laser_v, 0.0, rng);
  EXPECT_NEAR(s.true_ranges_m[90], 2.5 - 0.3, 1e-9);
  EXPECT_NEAR(s.ranges_m[90], 2.2f, 1e-6);
  EXPECT_TRUE(s.valid[90]);
  EXPECT_EQ(w.surfaces[static_cast<std::size_t>(s.hit_ids[90])].kind, "ceiling");
  // Beam 0 runs horizontally to the right wall.
  const double yaw = 0.4;
  EXPECT_NEAR(s.true_ranges_m[0], (1.0 + 0.3) / std::cos(yaw), 1e-9);
}

TEST(LaserSim, MissesAreInvalidAtMaxRange) {
  const World w = straightCorridor();
  const RayCaster caster(w);
  Rng rng(1);
  LaserOptions laser = w.sensors.laser_h;
  laser.max_range_m = 5.0;
  const SimulatedScan s = simulateScan(caster, Pose2D{10.0, 0.0, 0.0}, laser, 0.02, rng);
  EXPECT_FALSE(s.valid[90]);  // straight ahead, 10 m to the end wall
  EXPECT_EQ(s.ranges_m[90], 5.0f);
  EXPECT_EQ(s.hit_ids[90], -1);
  EXPECT_TRUE(s.valid[0]);  // the right wall, 1 m away
  EXPECT_NEAR(s.ranges_m[0], 1.0, 0.15);
}

TEST(LaserSim, NoisyRangeBeyondMaxRangeBecomesInvalid) {
  const World w = straightCorridor();
  const RayCaster caster(w);
  LaserOptions laser = w.sensors.laser_h;
  laser.max_range_m = 1.0;  // the right wall is exactly at max range
  int invalid = 0;
  for (int seed = 0; seed < 20; ++seed) {
    Rng rng(static_cast<std::uint64_t>(seed));
    const SimulatedScan s = simulateScan(caster, Pose2D{10.0, 0.0, 0.0}, laser, 0.02, rng);
    EXPECT_GE(s.hit_ids[0], 0);  // the true ray hits the wall either way
    if (!s.valid[0]) {
      ++invalid;
      EXPECT_EQ(s.ranges_m[0], 1.0f);
    } else {
      EXPECT_LE(s.ranges_m[0], 1.0f);
    }
  }
  EXPECT_GT(invalid, 3);
  EXPECT_LT(invalid, 17);
}

}  // namespace
}  // namespace pmap::sim
