#include "pmap/input/sensor_roles.h"

#include <gtest/gtest.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationImage.h>
#include <mrpt/obs/CObservationOdometry.h>

#include "pmap/common/error.h"
#include "pmap/config/section_reader.h"

namespace pmap::input {
namespace {

SensorsOptions load(const std::string& text) {
  const auto doc = config::IniDocument::parse(text, "t.ini");
  SensorsOptions o;
  config::loadOptions(doc, "Sensors", o, nullptr);
  return o;
}

TEST(SensorRoles, EmptyValueMeansUnlabelledAndNoneMeansNoSensor) {
  const SensorsOptions o = load("[Sensors]\npose_laser =\nstructure = none\n");
  EXPECT_EQ(o.pose_laser, std::vector<std::string>{""});
  EXPECT_TRUE(o.structure.empty());
  mrpt::obs::CObservation2DRangeScan scan;  // unlabelled
  const Roles r = RoleClassifier(o).classify(scan);
  EXPECT_TRUE(r.pose_laser);
  EXPECT_FALSE(r.structure);
}

TEST(SensorRoles, ClassAndLabelMustBothMatch) {
  const SensorsOptions o = load("[Sensors]\npose_laser = A\nstructure = A, B\nodometry = A\n");
  const RoleClassifier c(o);
  mrpt::obs::CObservation2DRangeScan scan;
  scan.sensorLabel = "A";
  const Roles both = c.classify(scan);
  EXPECT_TRUE(both.pose_laser && both.structure);
  EXPECT_FALSE(both.odometry);
  mrpt::obs::CObservationOdometry odo;
  odo.sensorLabel = "A";
  EXPECT_TRUE(c.classify(odo).odometry);
  mrpt::obs::CObservationImage image;
  image.sensorLabel = "A";
  EXPECT_FALSE(c.classify(image).any());
}

TEST(SensorRoles, InvalidCombinationsAreRejected) {
  EXPECT_THROW(load("[Sensors]\npose_laser = none\nstructure = none\n"), ConfigError);
  EXPECT_THROW(load("[Sensors]\nstructure = none, A\n"), ConfigError);
  EXPECT_THROW(load("[Sensors]\nmax_pose_gap_s = -1\n"), ConfigError);
  EXPECT_THROW(load("[Sensors]\nstrucure = A\n"), ConfigError);
  EXPECT_THROW(load("[Sensors]\npose_laser_aperture_deg = -1\n"), ConfigError);
  EXPECT_THROW(load("[Sensors]\npose_laser_aperture_deg = 400\n"), ConfigError);
  EXPECT_THROW(load("[Sensors]\npose_laser_aperture_deg = nan\n"), ConfigError);
  EXPECT_EQ(load("[Sensors]\npose_laser_aperture_deg = 180\n").pose_laser_aperture_deg, 180.0);
}

}  // namespace
}  // namespace pmap::input
