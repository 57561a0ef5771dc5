#include "pmap/input/observation_source.h"

#include <gtest/gtest.h>
#include <mrpt/obs/CObservation2DRangeScan.h>

#include <cmath>

#include "rawlog_fixtures.h"

namespace pmap::input {
namespace {
namespace fs = std::filesystem;
using testing::FixtureFormat;
using testing::FixtureOptions;

struct Collected {
  std::vector<std::int64_t> structure_indices;
  std::size_t pose_scans = 0;
  std::size_t odometry = 0;
  std::size_t steps_with_action = 0;
  std::vector<double> pose_apertures_deg;       ///< of the pose-laser scans handed on
  std::vector<double> structure_apertures_deg;  ///< of the other 2D scans
  InputStats stats;
};

Collected collect(const fs::path& path, SelectionOptions selection = {},
                  SensorsOptions sensors = {}) {
  RawlogReader reader(path);
  ObservationSource source(reader, RoleClassifier(sensors), selection);
  Collected c;
  InputStep step;
  while (source.next(step)) {
    c.steps_with_action += step.action ? 1 : 0;
    for (const auto& item : step.observations) {
      if (item.roles.structure) {
        c.structure_indices.push_back(item.structure_index);
      }
      c.pose_scans += item.roles.pose_laser ? 1 : 0;
      c.odometry += item.roles.odometry ? 1 : 0;
      if (const auto* scan =
              dynamic_cast<const mrpt::obs::CObservation2DRangeScan*>(item.obs.get())) {
        (item.roles.pose_laser ? c.pose_apertures_deg : c.structure_apertures_deg)
            .push_back(scan->aperture * 180.0 / M_PI);
      }
    }
  }
  c.stats = source.stats();
  return c;
}

fs::path fixture(const std::string& name, FixtureFormat format, bool leading = false) {
  const auto dir = testing::freshTestDir("source_" + name);
  FixtureOptions o;
  o.format = format;
  o.cycles = 10;
  o.leading_frame = leading;
  testing::writeFixtureRawlog(dir / "log.rawlog", o);
  return dir / "log.rawlog";
}

TEST(ObservationSource, AssignsRolesByLabelInBothFormats) {
  const Collected obs = collect(fixture("obs", FixtureFormat::kObservations));
  EXPECT_EQ(obs.stats.format, RawlogFormat::kObservations);
  EXPECT_EQ(obs.pose_scans, 10u);
  EXPECT_EQ(obs.odometry, 10u);
  ASSERT_EQ(obs.structure_indices.size(), 10u);
  const Collected sf = collect(fixture("sf", FixtureFormat::kSensoryFrames));
  EXPECT_EQ(sf.stats.format, RawlogFormat::kSensoryFrames);
  EXPECT_EQ(sf.pose_scans, 10u);
  EXPECT_EQ(sf.steps_with_action, 10u);
  EXPECT_EQ(sf.structure_indices, obs.structure_indices);
}

// Issue 15: MRPT 2.5.8's carmen2rawlog writes 0.5 deg per beam for CARMEN's
// 180-degree FLASER scans; [Sensors] pose_laser_aperture_deg puts it right,
// for the pose laser only, in both rawlog formats, and says it did.
TEST(ObservationSource, Item15_PoseLaserApertureIsReplacedWhenConfigured) {
  for (const FixtureFormat format : {FixtureFormat::kObservations, FixtureFormat::kSensoryFrames}) {
    const fs::path log = fixture("aperture", format);
    const Collected file = collect(log);
    ASSERT_EQ(file.pose_apertures_deg.size(), 10u);
    EXPECT_EQ(file.stats.aperture_replaced, 0u);
    SensorsOptions sensors;
    sensors.pose_laser_aperture_deg = 90.0;
    const Collected c = collect(log, {}, sensors);
    ASSERT_EQ(c.pose_apertures_deg.size(), 10u);
    for (const double a : c.pose_apertures_deg) {
      EXPECT_NEAR(a, 90.0, 1e-4);
    }
    EXPECT_EQ(c.structure_apertures_deg, file.structure_apertures_deg);  // not the pose laser's
    EXPECT_EQ(c.stats.aperture_replaced, 10u);
    EXPECT_NEAR(c.stats.file_aperture_deg, file.pose_apertures_deg.front(), 1e-4);
    EXPECT_EQ(c.stats.used_aperture_deg, 90.0);
  }
}

TEST(ObservationSource, StructureIndicesAreFileIndicesWhateverTheSelection) {
  const auto path = fixture("select", FixtureFormat::kObservations);
  SelectionOptions s;
  s.decimate = 3;
  const Collected dec = collect(path, s);
  EXPECT_EQ(dec.structure_indices, (std::vector<std::int64_t>{0, 3, 6, 9}));
  EXPECT_EQ(dec.stats.structure_decimated, 6u);
  EXPECT_EQ(dec.pose_scans, 10u);  // decimation only touches structure scans

  s = {};
  s.from_index = 9;  // records: 3 per cycle (odometry, LASER_H, LASER_V)
  s.to_index = 17;
  const Collected range = collect(path, s);
  EXPECT_EQ(range.structure_indices, (std::vector<std::int64_t>{3, 4, 5}));

  s = {};
  s.keep_labels = {"LASER_H"};
  const Collected keep = collect(path, s);
  EXPECT_TRUE(keep.structure_indices.empty());
  EXPECT_EQ(keep.pose_scans, 10u);
  EXPECT_EQ(keep.odometry, 0u);
}

TEST(ObservationSource, LeadingFrameIsKeptUnlessSkipped) {
  const auto path = fixture("leading", FixtureFormat::kSensoryFrames, true);
  EXPECT_EQ(collect(path).pose_scans, 11u);
  SelectionOptions s;
  s.skip_leading_frame = true;
  const Collected skipped = collect(path, s);
  EXPECT_EQ(skipped.pose_scans, 10u);
  EXPECT_TRUE(skipped.stats.leading_frame_skipped);
}

TEST(ObservationSource, UnassignedObservationsAreCountedAsIgnored) {
  SensorsOptions sensors;
  sensors.structure.clear();
  const Collected c = collect(fixture("ignored", FixtureFormat::kObservations), {}, sensors);
  EXPECT_TRUE(c.structure_indices.empty());
  EXPECT_EQ(c.stats.ignored.at("mrpt::obs::CObservation2DRangeScan:LASER_V"), 10u);
}

TEST(SelectionOptions, Validate) {
  SelectionOptions s;
  std::string why;
  EXPECT_TRUE(s.validate(&why));
  s.from_index = 5;
  s.to_index = 4;
  EXPECT_FALSE(s.validate(&why));
  s = {};
  s.decimate = 0;
  EXPECT_FALSE(s.validate(&why));
}

}  // namespace
}  // namespace pmap::input
