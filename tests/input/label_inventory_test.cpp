// Issue 13, item 2: a role whose labels the rawlog does not have is an error
// (exit 1) that lists what the file has; absent members of a role warn.
#include "pmap/input/label_inventory.h"

#include <gtest/gtest.h>

#include "pmap/common/error.h"
#include "rawlog_fixtures.h"

namespace pmap::input {
namespace {
namespace fs = std::filesystem;

fs::path fixture(const std::string& name, testing::FixtureFormat format) {
  const fs::path dir = testing::freshTestDir(name);
  testing::FixtureOptions o;
  o.cycles = 6;
  o.format = format;
  testing::writeFixtureRawlog(dir / "log.rawlog", o);
  return dir / "log.rawlog";
}

std::string errorOf(const SensorsOptions& s, const RolesInUse& used,
                    const std::vector<std::string>& keep, const LabelInventory& inv) {
  try {
    checkRoleLabels(s, used, keep, inv, "my.ini");
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

TEST(LabelInventory, Item2_CountsObservationsByClassAndLabel) {
  const LabelInventory inv =
      scanLabels(fixture("labels_count", testing::FixtureFormat::kObservations), 0);
  EXPECT_TRUE(inv.complete);
  EXPECT_TRUE(inv.error.empty());
  ASSERT_EQ(inv.labels.size(), 3u);
  std::size_t total = 0;
  for (const LabelCount& c : inv.labels) {
    EXPECT_EQ(c.count, 6u) << c.label;
    total += c.count;
  }
  EXPECT_EQ(total, inv.records);
  EXPECT_NE(inv.describe().find("'LASER_H' (CObservation2DRangeScan) x 6"), std::string::npos)
      << inv.describe();
}

TEST(LabelInventory, Item2_ReadsOnlyTheFirstRecordsWhenAsked) {
  const LabelInventory inv =
      scanLabels(fixture("labels_first", testing::FixtureFormat::kObservations), 5);
  EXPECT_EQ(inv.records, 5u);
  EXPECT_FALSE(inv.complete);
}

TEST(LabelInventory, Item2_WrongPoseLaserLabelIsAnErrorListingTheFile) {
  const LabelInventory inv =
      scanLabels(fixture("labels_wrong", testing::FixtureFormat::kObservations), 1000);
  SensorsOptions s;
  s.pose_laser = {"LASER_HORIZ"};
  const std::string e = errorOf(s, RolesInUse{}, {}, inv);
  EXPECT_NE(e.find("my.ini: [Sensors] pose_laser = LASER_HORIZ"), std::string::npos) << e;
  EXPECT_NE(e.find("'LASER_H' (CObservation2DRangeScan) x 6"), std::string::npos) << e;
  EXPECT_NE(e.find("'ODOMETRY' (CObservationOdometry) x 6"), std::string::npos) << e;
  // The same label is fine when the role is not used (--poses).
  RolesInUse given_poses;
  given_poses.pose_laser = false;
  EXPECT_EQ(errorOf(s, given_poses, {}, inv), "");
}

TEST(LabelInventory, Item2_ALabelOfTheWrongClassDoesNotCount) {
  const LabelInventory inv =
      scanLabels(fixture("labels_class", testing::FixtureFormat::kObservations), 1000);
  SensorsOptions s;
  s.pose_laser = {"ODOMETRY"};  // present, but not a 2D scan
  EXPECT_NE(errorOf(s, RolesInUse{}, {}, inv).find("pose_laser = ODOMETRY"), std::string::npos);
}

TEST(LabelInventory, Item2_AbsentMembersOfARoleWarnOnce) {
  const LabelInventory inv =
      scanLabels(fixture("labels_members", testing::FixtureFormat::kObservations), 1000);
  SensorsOptions s;
  s.structure = {"OPENNI2", "LASER_V", "Velodyne1_SCAN"};
  s.cameras.clear();  // none
  const auto warnings = checkRoleLabels(s, RolesInUse{}, {}, inv, "my.ini");
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_NE(warnings[0].find("'OPENNI2'"), std::string::npos) << warnings[0];
  EXPECT_NE(warnings[1].find("'Velodyne1_SCAN'"), std::string::npos) << warnings[1];
}

TEST(LabelInventory, Item2_NoneAndUnlabelledKeepTheirMeaning) {
  const LabelInventory inv =
      scanLabels(fixture("labels_none", testing::FixtureFormat::kObservations), 1000);
  SensorsOptions s;
  s.cameras.clear();  // `none`: not checked
  EXPECT_EQ(errorOf(s, RolesInUse{}, {}, inv), "");
  s.pose_laser = {""};  // unlabelled: the fixture has none
  EXPECT_NE(errorOf(s, RolesInUse{}, {}, inv).find("pose_laser = "), std::string::npos);
}

TEST(LabelInventory, Item2_AFileWithoutCamerasOrOdometryWarnsInsteadOfFailing) {
  const LabelInventory inv =
      scanLabels(fixture("labels_optional", testing::FixtureFormat::kObservations), 1000);
  SensorsOptions s;  // cameras = CAMERA_LEFT, CAMERA_RIGHT: the fixture has no images
  const auto warnings = checkRoleLabels(s, RolesInUse{}, {}, inv, "my.ini");
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("no camera images"), std::string::npos) << warnings[0];
  // Odometry under another label than the file's is a wrong label: an error.
  s.odometry = {"ODOM"};
  EXPECT_NE(errorOf(s, RolesInUse{}, {}, inv).find("odometry = ODOM"), std::string::npos);
}

TEST(LabelInventory, Item2_ActionsAreOdometryWhateverTheLabels) {
  const LabelInventory inv =
      scanLabels(fixture("labels_sf", testing::FixtureFormat::kSensoryFrames), 1000);
  EXPECT_EQ(inv.odometry_actions, 6u);
  SensorsOptions s;
  s.odometry = {"NO_SUCH_LABEL"};
  s.cameras.clear();
  EXPECT_EQ(errorOf(s, RolesInUse{}, {}, inv), "");
}

TEST(LabelInventory, Item2_KeepLabelIsChecked) {
  const LabelInventory inv =
      scanLabels(fixture("labels_keep", testing::FixtureFormat::kObservations), 1000);
  SensorsOptions s;
  s.cameras.clear();
  EXPECT_NE(errorOf(s, RolesInUse{}, {"LASER_X"}, inv).find("--keep-label = LASER_X"),
            std::string::npos);
  const auto warnings = checkRoleLabels(s, RolesInUse{}, {"LASER_H", "LASER_X"}, inv, "my.ini");
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("'LASER_X'"), std::string::npos);
}

}  // namespace
}  // namespace pmap::input
