#include "pmap/poses/icp_pose_tracker.h"

#include <gtest/gtest.h>
#include <mrpt/obs/CObservation2DRangeScan.h>

#include <cmath>
#include <random>

#include "pmap/config/strict_mrpt_config.h"
#include "pmap/input/observation_source.h"
#include "pmap/poses/pose_stage.h"
#include "rawlog_fixtures.h"
#include "segment_world.h"

namespace pmap::poses {
namespace {
namespace fs = std::filesystem;

const char* kIcpIni = R"(
[ICP]
ICP_algorithm = icpLevenbergMarquardt
maxIterations = 80
thresholdDist = 0.3
smallestThresholdDist = 0.05
[MappingApplication]
localizationLinDistance = 0.2
localizationAngDistance = 5
insertionLinDistance = 1.2
insertionAngDistance = 45
pointsMap_count = 1
[MappingApplication_pointsMap_00_insertOpts]
minDistBetweenLaserPoints = 0.05
isPlanarMap = 1
)";

Trajectory run(const fs::path& rawlog) {
  const auto doc = config::IniDocument::parse(kIcpIni, "icp.ini");
  config::StrictMrptConfig cfg(doc, {"ICP", "MappingApplication*"});
  PoseStage stage(std::make_unique<IcpPoseTracker>(cfg), MotionLimits{});
  cfg.checkAllRead();
  input::RawlogReader reader(rawlog);
  input::ObservationSource source(reader, input::RoleClassifier({}), {});
  input::InputStep step;
  while (source.next(step)) {
    stage.process(step, rawlog.string());
  }
  return stage.trajectory();
}

TEST(IcpPoseTracker, FollowsOdometryInBothFormatsAlike) {
  const auto dir = pmap::testing::freshTestDir("icp_tracker");
  pmap::testing::FixtureOptions o;
  o.cycles = 25;
  pmap::testing::writeFixtureRawlog(dir / "obs.rawlog", o);
  o.format = pmap::testing::FixtureFormat::kSensoryFrames;
  pmap::testing::writeFixtureRawlog(dir / "sf.rawlog", o);
  const Trajectory a = run(dir / "obs.rawlog");
  const Trajectory b = run(dir / "sf.rawlog");
  ASSERT_EQ(a.size(), 25u);
  ASSERT_EQ(b.size(), 25u);
  // Exact odometry and an end wall ahead: ICP must keep the true motion, one
  // pose per cycle at the scan's timestamp, both formats alike.
  EXPECT_NEAR(a.poses().back().pose.x, 0.4 * 0.2 * 24, 0.05);
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_DOUBLE_EQ(a.poses()[i].t, b.poses()[i].t);
    EXPECT_NEAR(a.poses()[i].pose.x, b.poses()[i].pose.x, 1e-6);
    EXPECT_NEAR(a.poses()[i].pose.y, b.poses()[i].pose.y, 1e-6);
    EXPECT_NEAR(a.poses()[i].pose.yaw, b.poses()[i].pose.yaw, 1e-6);
  }
}

// A 181-beam, 180-degree scan of `world` from `pose`, as MRPT's observation.
mrpt::obs::CObservation2DRangeScan::Ptr scanAt(const std::vector<testing::Segment>& world,
                                               const Pose2& pose, double t) {
  auto obs = std::make_shared<mrpt::obs::CObservation2DRangeScan>();
  obs->aperture = static_cast<float>(M_PI);
  obs->rightToLeft = true;
  obs->maxRange = 20.0f;
  obs->resizeScan(181);
  for (int i = 0; i <= 180; ++i) {
    const double a = pose.theta + (i - 90) * M_PI / 180.0;
    const double r = testing::rayHit(world, {pose.x, pose.y}, {std::cos(a), std::sin(a)}, 20.0);
    obs->setScanRange(static_cast<std::size_t>(i), static_cast<float>(r));
    obs->setScanRangeValidity(static_cast<std::size_t>(i), r < 20.0);
  }
  obs->timestamp = mrpt::Clock::fromDouble(t);
  obs->sensorLabel = "LASER";
  return obs;
}

// Issue 15 item 1: the loop-closing stage replaces the front end's map with
// the one rebuilt from the pose graph. The replacement keeps the pose, and
// the next scan is matched against the new map: a map moved 0.3 m along x
// moves the pose by as much.
TEST(IcpPoseTracker, Item15_ReplaceMapKeepsThePoseAndTheNextMatchUsesTheNewMap) {
  std::vector<testing::Segment> world;
  testing::addBox(world, -3, -2, 5, 3);
  testing::addBox(world, 1.0, 1.0, 1.6, 1.4);
  const auto doc = config::IniDocument::parse(kIcpIni, "icp.ini");
  config::StrictMrptConfig cfg(doc, {"ICP", "MappingApplication*"});
  IcpPoseTracker tracker(cfg);
  const Pose2 at{0.0, 0.0, 0.0};
  tracker.processObservation(scanAt(world, at, 1.0), false);
  const mrpt::math::TPose3D first = tracker.currentPose();
  EXPECT_NEAR(first.x, 0.0, 1e-9);
  std::mt19937 rng(1);
  std::vector<Eigen::Vector2d> moved;
  for (const Eigen::Vector2d& p : testing::scan(world, at, rng, 0.0, 20.0)) {
    moved.emplace_back(p.x() + 0.3, p.y());
  }
  tracker.replaceMap(moved);
  EXPECT_EQ(tracker.currentPose().x, first.x);
  tracker.processObservation(scanAt(world, at, 1.1), false);
  EXPECT_NEAR(tracker.currentPose().x, 0.3, 0.02);
  EXPECT_NEAR(tracker.currentPose().y, 0.0, 0.02);
}

}  // namespace
}  // namespace pmap::poses
