#include "pmap/sim/sensor_options.h"

#include <gtest/gtest.h>

#include "pmap/sim/world_spec.h"

namespace pmap::sim {
namespace {

TEST(SensorOptions, DefaultsAreValidAndThePapersRobot) {
  const SensorOptions s;
  std::string why;
  EXPECT_TRUE(s.validate(&why)) << why;
  EXPECT_EQ(s.laser_h.label, "LASER_H");
  EXPECT_EQ(s.laser_v.time_offset_s, 0.1);
  EXPECT_EQ(s.cameras.time_offset_s, 0.05);
  EXPECT_EQ(s.cameras.rate_hz, 2.0);
  EXPECT_EQ(s.cameras.mounts[0].look, "left");
  EXPECT_EQ(s.cameras.mounts[1].look, "right");
  EXPECT_EQ(s.start_time_s, 1767225600.0);
  EXPECT_TRUE(NoiseOptions().validate(&why)) << why;
  EXPECT_FALSE(s.cameras.lens.hasDistortion());
  EXPECT_EQ(s.cameras.exposure.gain[1], 1.2);
}

TEST(SensorOptions, ValidateNamesTheViolatedRule) {
  std::string why;
  SensorOptions s;
  s.laser_v.beams = 1;
  EXPECT_FALSE(s.validate(&why));
  EXPECT_NE(why.find("laser_v: beams"), std::string::npos) << why;
  s = SensorOptions();
  s.laser_v.time_offset_s = 0.3;  // longer than a 5 Hz cycle
  EXPECT_FALSE(s.validate(&why));
  EXPECT_NE(why.find("time offsets"), std::string::npos) << why;
  s = SensorOptions();
  s.cameras.mounts[0].look = "up";
  EXPECT_FALSE(s.validate(&why));
  s = SensorOptions();
  s.cameras.exposure.gain = {1.3, 1.1};
  EXPECT_FALSE(s.validate(&why));
  EXPECT_NE(why.find("cameras: exposure.gain"), std::string::npos) << why;
  NoiseOptions n;
  n.range_sigma_m = -1.0;
  EXPECT_FALSE(n.validate(&why));
  EXPECT_NE(why.find("range_sigma_m"), std::string::npos);
}

TEST(WorldSpec, PathValidation) {
  PathSpec p;
  std::string why;
  EXPECT_FALSE(p.validate(&why));
  p.waypoints = {Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 0)};
  EXPECT_TRUE(p.validate(&why)) << why;
  p.speed_m_s = 0.0;
  EXPECT_FALSE(p.validate(&why));
  EXPECT_NE(why.find("speed_m_s"), std::string::npos);
}

}  // namespace
}  // namespace pmap::sim
