#include "pmap/sim/rawlog_writer.h"

#include <gtest/gtest.h>

#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CSensoryFrame.h>

#include "pmap/common/error.h"
#include "pmap/sim/observation_factory.h"
#include "sim_test_support.h"

namespace pmap::sim {
namespace {

CycleRecord cycle(int k) {
  const SensorOptions sensors;
  SimulatedScan scan;
  scan.ranges_m.assign(181, 1.0f + static_cast<float>(k));
  scan.valid.assign(181, 1);
  CycleRecord r;
  const auto t = simTimestamp(1767225600.0, k * 0.2);
  r.odometry = makeOdometryObservation("ODOMETRY", Pose2D{0.08 * k, 0, 0}, t);
  r.action = makeOdometryAction(Pose2D{k == 0 ? 0.0 : 0.08, 0, 0}, t);
  r.observations.push_back(makeScanObservation(sensors.laser_h, scan, t, 0.02));
  r.observations.push_back(
      makeScanObservation(sensors.laser_v, scan, simTimestamp(1767225600.0, k * 0.2 + 0.1), 0.02));
  return r;
}

TEST(RawlogWriter, ObservationsFormatIsAFlatSequence) {
  const auto dir = test::freshDir("rawlog_obs");
  {
    RawlogWriter w(dir / "a.rawlog", RawlogFormat::kObservations);
    for (int k = 0; k < 3; ++k) {
      w.write(cycle(k));
    }
    w.finish();  // writes the path it was given (the caller's temporary)
    EXPECT_EQ(w.objectsWritten(), 9u);
  }
  const auto objects = test::readRawlog(dir / "a.rawlog");
  ASSERT_EQ(objects.size(), 9u);
  EXPECT_TRUE(std::dynamic_pointer_cast<mrpt::obs::CObservationOdometry>(objects[0]));
  const auto v = std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(objects[5]);
  ASSERT_TRUE(v);
  EXPECT_EQ(v->sensorLabel, "LASER_V");
  EXPECT_EQ(v->getScanRange(0), 2.0f);
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir),
                          std::filesystem::directory_iterator()),
            1);
}

TEST(RawlogWriter, SensoryFrameFormatAlternatesActionsAndFrames) {
  const auto dir = test::freshDir("rawlog_sf");
  RawlogWriter w(dir / "b.rawlog", RawlogFormat::kSensoryFrames);
  for (int k = 0; k < 3; ++k) {
    w.write(cycle(k));
  }
  w.finish();
  const auto objects = test::readRawlog(dir / "b.rawlog");
  ASSERT_EQ(objects.size(), 6u);
  for (std::size_t i = 0; i < objects.size(); i += 2) {
    EXPECT_TRUE(std::dynamic_pointer_cast<mrpt::obs::CActionCollection>(objects[i]));
    const auto sf = std::dynamic_pointer_cast<mrpt::obs::CSensoryFrame>(objects[i + 1]);
    ASSERT_TRUE(sf);
    EXPECT_EQ(sf->size(), 2u);
  }
}

TEST(RawlogWriter, UnfinishedWriterLeavesNothing) {
  const auto dir = test::freshDir("rawlog_abort");
  {
    RawlogWriter w(dir / "c.rawlog", RawlogFormat::kObservations);
    w.write(cycle(0));
  }
  EXPECT_TRUE(std::filesystem::is_empty(dir));
}

TEST(RawlogWriter, UnwritableDirectoryIsAnOutputError) {
  EXPECT_THROW(RawlogWriter("/proc/pmap-no-such-dir/x.rawlog", RawlogFormat::kObservations),
               OutputError);
}

TEST(RawlogWriter, FormatNames) {
  EXPECT_EQ(parseRawlogFormat("obs"), RawlogFormat::kObservations);
  EXPECT_EQ(parseRawlogFormat("sf"), RawlogFormat::kSensoryFrames);
  EXPECT_FALSE(parseRawlogFormat("raw"));
  EXPECT_STREQ(rawlogFormatName(RawlogFormat::kSensoryFrames), "sf");
}

}  // namespace
}  // namespace pmap::sim
