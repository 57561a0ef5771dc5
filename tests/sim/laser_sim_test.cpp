#include "pmap/sim/laser_sim.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose3D.h>

#include "pmap/sim/observation_factory.h"
#include "pmap/sim/world_builder.h"
#include "pmap/sim/world_loader.h"

namespace pmap::sim {
namespace {

NoiseOptions gaussian(double sigma_m) {
  NoiseOptions n;
  n.range_sigma_m = sigma_m;
  return n;
}

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
  const SimulatedScan s =
      simulateScan(caster, Pose2D{5.0, 0.3, 0.4}, w.sensors.laser_v, gaussian(0.0), rng);
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
  const SimulatedScan s = simulateScan(caster, Pose2D{10.0, 0.0, 0.0}, laser, gaussian(0.02), rng);
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
    const SimulatedScan s =
        simulateScan(caster, Pose2D{10.0, 0.0, 0.0}, laser, gaussian(0.02), rng);
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

// The beam at angle `deg` (0 ahead, positive to the left) of the 181-beam
// horizontal laser.
std::size_t beamAt(int deg) {
  return static_cast<std::size_t>(90 + deg);
}

// The range errors of one beam over `runs` scans from (10, 0, 0).
std::vector<double> rangeErrors(const RayCaster& caster, const LaserOptions& laser,
                                const NoiseOptions& noise, std::size_t beam, int runs) {
  std::vector<double> out;
  for (int seed = 0; seed < runs; ++seed) {
    Rng rng(static_cast<std::uint64_t>(seed));
    const SimulatedScan s = simulateScan(caster, Pose2D{10.0, 0.0, 0.0}, laser, noise, rng);
    out.push_back(s.ranges_m[beam] - s.true_ranges_m[beam]);
  }
  return out;
}

double rms(const std::vector<double>& v) {
  double sum = 0;
  for (const double x : v) {
    sum += x * x;
  }
  return std::sqrt(sum / static_cast<double>(v.size()));
}

// Real lasers (LaserErrorOptions): the noise grows with the range and with
// the incidence. From (10, 0) in a 2 m corridor whose end wall is 10 m ahead:
// the beam ahead meets the end wall head on at 10 m, the beam 90 deg to the
// right the side wall head on at 1 m, the one 30 deg right of ahead the side
// wall at 2 m and 60 deg from its normal (1 / cos = 2).
TEST(LaserSim, RangeNoiseFollowsRangeAndIncidence) {
  const World w = straightCorridor();
  const RayCaster caster(w);
  const LaserOptions& laser = w.sensors.laser_h;
  NoiseOptions by_range = gaussian(0.0);
  by_range.laser.sigma_per_m = 0.01;
  EXPECT_NEAR(rms(rangeErrors(caster, laser, by_range, beamAt(0), 400)), 0.10, 0.01);
  EXPECT_NEAR(rms(rangeErrors(caster, laser, by_range, beamAt(-90), 400)), 0.01, 0.001);
  NoiseOptions by_incidence = gaussian(0.01);
  by_incidence.laser.incidence_factor = 1.0;
  EXPECT_NEAR(rms(rangeErrors(caster, laser, by_incidence, beamAt(-90), 400)), 0.01, 0.001);
  EXPECT_NEAR(rms(rangeErrors(caster, laser, by_incidence, beamAt(-30), 400)), 0.02, 0.002);
  // Off, the same draws as before the effects existed: the Gaussian alone.
  const std::vector<double> plain = rangeErrors(caster, laser, gaussian(0.01), beamAt(-30), 50);
  NoiseOptions off = gaussian(0.01);
  off.laser.mixed_pixel_jump_m = 5.0;  // no effect without its probability
  EXPECT_EQ(plain, rangeErrors(caster, laser, off, beamAt(-30), 50));
}

// Beams meeting the side walls within 10 deg of grazing (5.7-10 deg off the
// axis ahead) are lost; the end wall and steeper side-wall beams are not.
TEST(LaserSim, GrazingBeamsReturnNothing) {
  const World w = straightCorridor();
  const RayCaster caster(w);
  NoiseOptions noise = gaussian(0.0);
  noise.laser.grazing_dropout_deg = 80.0;
  Rng rng(1);
  const SimulatedScan s =
      simulateScan(caster, Pose2D{10.0, 0.0, 0.0}, w.sensors.laser_h, noise, rng);
  for (const int deg : {-9, -8, -7, 7, 8, 9}) {
    EXPECT_FALSE(s.valid[beamAt(deg)]) << deg;
    EXPECT_GE(s.hit_ids[beamAt(deg)], 0) << deg;  // the true ray still hits
  }
  for (const int deg : {-30, -11, -3, 0, 3, 11, 30}) {
    EXPECT_TRUE(s.valid[beamAt(deg)]) << deg;
  }
}

// Lost and spurious returns come at their probabilities; a spurious one is
// short of the true hit and lies on no object.
TEST(LaserSim, DropoutsAndSpuriousReturnsComeAtTheirRates) {
  const World w = straightCorridor();
  const RayCaster caster(w);
  NoiseOptions noise = gaussian(0.0);
  noise.laser.dropout_probability = 0.3;
  noise.laser.spurious_probability = 0.1;
  int beams = 0, lost = 0, spurious = 0;
  for (int seed = 0; seed < 40; ++seed) {
    Rng rng(static_cast<std::uint64_t>(seed));
    const SimulatedScan s =
        simulateScan(caster, Pose2D{10.0, 0.0, 0.0}, w.sensors.laser_h, noise, rng);
    for (std::size_t i = 0; i < s.ranges_m.size(); ++i) {
      ++beams;
      if (s.valid[i] && s.hit_ids[i] < 0) {
        ++spurious;
        EXPECT_LT(s.ranges_m[i], s.true_ranges_m[i]);
        EXPECT_GE(s.ranges_m[i], 0.1f);
      } else if (!s.valid[i]) {
        ++lost;
      }
    }
  }
  // 7,240 beams: the binomial's standard deviation is under 0.6 % of them.
  EXPECT_NEAR(static_cast<double>(spurious) / beams, 0.1, 0.02);
  EXPECT_NEAR(static_cast<double>(lost) / beams, 0.9 * 0.3, 0.03);
}

/// A corridor along x closed at x = 20, with a pane across it at x = 14 of
/// kind `pane` ("" for none).
World corridorWithPane(const std::string& pane) {
  const std::string rect =
      pane.empty()
          ? ""
          : R"(, "rectangles": [{"kind": ")" + pane +
                R"(", "corners": [[14, 1, 0], [14, -1, 0], [14, -1, 2.5], [14, 1, 2.5]]}])";
  return buildWorld(parseWorldText(
      R"({"name": "c", "corridors": [{"centreline": [[0, 0], [20, 0]], "width_m": 2.0,
          "height_m": 2.5}], "path": {"waypoints": [[1, 0], [12, 0]]})" +
          rect + "}",
      "w.json"));
}

// Glass: a beam meeting the pane within glass_return_deg of its normal
// returns from it (as from an opaque pane), any other returns from what lies
// behind (as if there were no pane).
TEST(LaserSim, Issue16_ABeamGoesThroughGlassUnlessItMeetsThePaneSquarely) {
  const World glass = corridorWithPane("glass");
  const World opaque = corridorWithPane("wall");
  const World none = corridorWithPane("");
  const RayCaster g(glass), o(opaque), n(none);
  const int pane = static_cast<int>(none.surfaces.size());
  const Pose2D robot{10.0, 0.05, 0.02};
  const LaserOptions& laser = glass.sensors.laser_h;
  NoiseOptions exact = gaussian(0.0);
  const double cos_return = std::cos(exact.laser.glass_return_deg * M_PI / 180.0);
  Rng r1(1), r2(1), r3(1);
  const SimulatedScan sg = simulateScan(g, robot, laser, exact, r1);
  const SimulatedScan so = simulateScan(o, robot, laser, exact, r2);
  const SimulatedScan sn = simulateScan(n, robot, laser, exact, r3);
  int specular = 0, through = 0;
  for (std::size_t i = 0; i < sg.ranges_m.size(); ++i) {
    const Eigen::Vector3d dir = beamDirectionInWorld(robot, laser, static_cast<int>(i));
    const bool on_pane = so.hit_ids[i] == pane;
    const bool square = on_pane && std::abs(dir.x()) >= cos_return;  // the pane's normal is -x
    const SimulatedScan& expected = !on_pane || square ? so : sn;
    EXPECT_EQ(sg.hit_ids[i], expected.hit_ids[i]) << i;
    EXPECT_DOUBLE_EQ(sg.true_ranges_m[i], expected.true_ranges_m[i]) << i;
    specular += square ? 1 : 0;
    through += on_pane && !square ? 1 : 0;
  }
  EXPECT_GT(specular, 5);
  EXPECT_GT(through, 2);
}

TEST(LaserSim, Issue16_GlassDropoutLosesOnlyBeamsThatWentThroughGlass) {
  const World glass = corridorWithPane("glass");
  const World opaque = corridorWithPane("wall");
  const RayCaster g(glass), o(opaque);
  const int pane = static_cast<int>(glass.surfaces.size()) - 1;
  const Pose2D robot{10.0, 0.05, 0.02};
  const LaserOptions& laser = glass.sensors.laser_h;
  NoiseOptions noise = gaussian(0.0);
  noise.laser.glass_dropout_probability = 1.0;
  const double cos_return = std::cos(noise.laser.glass_return_deg * M_PI / 180.0);
  Rng r1(1), r2(1);
  const SimulatedScan sg = simulateScan(g, robot, laser, noise, r1);
  const SimulatedScan so = simulateScan(o, robot, laser, noise, r2);
  int lost = 0;
  for (std::size_t i = 0; i < sg.ranges_m.size(); ++i) {
    const Eigen::Vector3d dir = beamDirectionInWorld(robot, laser, static_cast<int>(i));
    const bool through = so.hit_ids[i] == pane && std::abs(dir.x()) < cos_return;
    EXPECT_EQ(sg.valid[i] == 0, through) << i;
    lost += through ? 1 : 0;
  }
  EXPECT_GT(lost, 2);
}

// At a depth edge (a column 4.7 m ahead in front of the end wall 10 m
// ahead), mixed returns lie between the two surfaces, on neither; along the
// side walls met at grazing angles, where neighbouring ranges jump too, the
// spot stays on the wall.
TEST(LaserSim, MixedPixelsLieBetweenTheTwoSidesOfADepthEdge) {
  const World w = buildWorld(parseWorldText(
      R"({"name": "c", "corridors": [{"centreline": [[0, 0], [20, 0]], "width_m": 2.0,
          "height_m": 2.5}], "clutter": [{"kind": "column", "shape": "cylinder",
          "centre": [15, 0], "radius_m": 0.3, "z_min_m": 0.0, "z_max_m": 2.5}],
          "path": {"waypoints": [[1, 0], [19, 0]]}})",
      "w.json"));
  const RayCaster caster(w);
  const Pose2D robot{10.0, 0.0, 0.0};
  Rng plain_rng(1);
  const SimulatedScan truth =
      simulateScan(caster, robot, w.sensors.laser_h, gaussian(0.0), plain_rng);
  NoiseOptions noise = gaussian(0.0);
  noise.laser.mixed_pixel_probability = 1.0;
  Rng rng(1);
  const SimulatedScan s = simulateScan(caster, robot, w.sensors.laser_h, noise, rng);
  int mixed = 0, grazing_jumps = 0;
  for (std::size_t i = 1; i + 1 < s.ranges_m.size(); ++i) {
    bool edge = false;
    double lo = truth.true_ranges_m[i], hi = lo;
    for (const std::size_t j : {i - 1, i + 1}) {
      const bool jump = std::abs(truth.true_ranges_m[j] - truth.true_ranges_m[i]) > 0.3;
      if (jump && truth.hit_ids[j] != truth.hit_ids[i]) {
        edge = true;
        lo = std::min(lo, truth.true_ranges_m[j]);
        hi = std::max(hi, truth.true_ranges_m[j]);
      }
      grazing_jumps += jump && truth.hit_ids[j] == truth.hit_ids[i] ? 1 : 0;
    }
    if (!edge) {
      EXPECT_NEAR(s.ranges_m[i], truth.ranges_m[i], 1e-5) << i;  // on its surface, exactly
      EXPECT_EQ(s.hit_ids[i], truth.hit_ids[i]) << i;
      continue;
    }
    ++mixed;
    EXPECT_EQ(s.hit_ids[i], -1) << i;
    EXPECT_GT(s.ranges_m[i], lo - 1e-5) << i;
    EXPECT_LT(s.ranges_m[i], hi + 1e-5) << i;
  }
  EXPECT_GE(mixed, 4);           // both sides of both of the column's edges
  EXPECT_GT(grazing_jumps, 10);  // the side walls far ahead: jumps, but no edge
}

}  // namespace
}  // namespace pmap::sim
