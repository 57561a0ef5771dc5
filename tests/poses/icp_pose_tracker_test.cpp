#include "pmap/poses/icp_pose_tracker.h"

#include <gtest/gtest.h>

#include "pmap/config/strict_mrpt_config.h"
#include "pmap/input/observation_source.h"
#include "pmap/poses/pose_stage.h"
#include "rawlog_fixtures.h"

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
  const auto dir = testing::freshTestDir("icp_tracker");
  testing::FixtureOptions o;
  o.cycles = 25;
  testing::writeFixtureRawlog(dir / "obs.rawlog", o);
  o.format = testing::FixtureFormat::kSensoryFrames;
  testing::writeFixtureRawlog(dir / "sf.rawlog", o);
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

}  // namespace
}  // namespace pmap::poses
