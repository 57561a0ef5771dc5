#include "pmap/sim/people.h"

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>

#include "pmap/common/error.h"
#include "pmap/sim/laser_sim.h"
#include "pmap/sim/simulator.h"
#include "pmap/sim/world_builder.h"
#include "pmap/sim/world_loader.h"
#include "sim_test_support.h"

namespace pmap::sim {
namespace {

/// A corridor along x (y in [-1.5, 1.5], 2.5 m high) with a bin and, when
/// `people` is not empty, that "people" block.
std::string corridorJson(const std::string& people, const std::string& path) {
  return R"({"name": "p", "corridors": [{"centreline": [[0, 0], [20, 0]], "width_m": 3.0,
      "height_m": 2.5, "posters": [{"leg": 0, "side": "left", "centre_m": 3.0}]}],
      "clutter": [{"kind": "bin", "centre": [18, -1.0], "radius_m": 0.2, "z_max_m": 0.8}],
      "path": )" +
         path + (people.empty() ? "" : R"(, "people": )" + people) + "}";
}

const char* const kPath = R"({"waypoints": [[1, -0.6], [15, -0.6]]})";
const char* const kWalker =
    R"([{"waypoints": [[4, 0.8], [16, 0.8]], "speed_m_s": 1.0, "start_s": 2.0}])";

TEST(People, Issue16_APersonStandsThenWalksThereAndBack) {
  PersonSpec s;
  s.waypoints = {Eigen::Vector2d(0, 0), Eigen::Vector2d(10, 0)};
  s.speed_m_s = 1.0;
  s.start_s = 2.0;
  const WalkingPerson p(s, "w.json");
  const std::pair<double, double> expected[] = {{0.0, 0.0},   {2.0, 0.0},        {7.0, 5.0},
                                                {12.0, 10.0}, {17.0, 5.0},       {22.0, 0.0},
                                                {27.0, 5.0},  {33.5, 10.0 - 1.5}};
  for (const auto& [t, x] : expected) {
    const VerticalCylinder c = p.at(t);
    EXPECT_NEAR(c.centre.x(), x, 1e-9) << "t = " << t;
    EXPECT_NEAR(c.centre.y(), 0.0, 1e-9) << "t = " << t;
  }
  EXPECT_EQ(p.at(5.0).radius_m, 0.25);
  EXPECT_EQ(p.at(5.0).z_max_m, 1.75);
}

TEST(People, Issue16_TheirIdsFollowThePosters) {
  const World w = buildWorld(parseWorldText(corridorJson(kWalker, kPath), "w.json"));
  ASSERT_EQ(w.people.size(), 1u);
  ASSERT_EQ(w.posters.size(), 1u);
  EXPECT_EQ(w.people[0].id, w.posters[0].id + 1);
  EXPECT_EQ(w.posters[0].id, static_cast<int>(w.surfaces.size() + w.clutter.size()));
}

TEST(People, Issue16_TheLasersSeeAPersonWhereItIsAtTheScansTime) {
  const World w = buildWorld(parseWorldText(corridorJson(kWalker, kPath), "w.json"));
  const RayCaster caster(w);
  const LaserOptions& laser = w.sensors.laser_h;
  const Pose2D robot{10.0, -0.6, M_PI / 2};  // looking across the corridor, at the person's lane
  const int ahead = (laser.beams - 1) / 2;
  const double y0 = laserToWorld(robot, laser).translation.y();
  NoiseOptions exact;
  exact.range_sigma_m = 0.0;
  Rng rng(1);
  // t = 8 s: the person walked 6 m from x = 4 and stands in the beam.
  const SimulatedScan with = simulateScan(caster, robot, laser, exact, rng, 8.0);
  EXPECT_EQ(with.hit_ids[static_cast<std::size_t>(ahead)], w.people[0].id);
  EXPECT_NEAR(with.true_ranges_m[static_cast<std::size_t>(ahead)], 0.8 - 0.25 - y0, 1e-9);
  // t = 0 s: it still stands at x = 4; the beam meets the left wall.
  const SimulatedScan without = simulateScan(caster, robot, laser, exact, rng, 0.0);
  const int wall = without.hit_ids[static_cast<std::size_t>(ahead)];
  ASSERT_GE(wall, 0);
  EXPECT_EQ(w.surfaces[static_cast<std::size_t>(wall)].kind, "wall");
  EXPECT_NEAR(without.true_ranges_m[static_cast<std::size_t>(ahead)], 1.5 - y0, 1e-9);
}

/// The message the Simulator throws for `world` (or "" if none).
std::string simulatorError(const std::string& name, const std::string& world,
                           std::optional<double> duration_s = std::nullopt) {
  const std::filesystem::path dir = test::freshDir(name);
  SimulatorOptions o;
  o.duration_s = duration_s;
  o.world_file = test::writeText(dir / "w.json", world);
  o.out_prefix = (dir / "run").string();
  o.cameras = false;
  o.progress = false;
  try {
    Simulator s(o);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

TEST(People, Issue16_APersonWalkingIntoTheRobotIsRefused) {
  // Walking down the robot's lane towards it.
  const std::string e = simulatorError(
      "people_robot",
      corridorJson(R"([{"waypoints": [[16, -0.6], [2, -0.6]], "speed_m_s": 1.0}])", kPath));
  EXPECT_NE(e.find("w.json: people[0]: the person walks into the robot at t = "), std::string::npos)
      << e;
  EXPECT_EQ(simulatorError("people_ok", corridorJson(kWalker, kPath)), "");
  // A run that ends before they meet (--duration) is fine.
  EXPECT_EQ(
      simulatorError(
          "people_early",
          corridorJson(R"([{"waypoints": [[16, -0.6], [2, -0.6]], "speed_m_s": 1.0}])", kPath),
          3.0),
      "");
}

TEST(People, Issue16_APersonWalkingThroughAWallIsRefused) {
  const std::string e = simulatorError(
      "people_wall", corridorJson(R"([{"waypoints": [[6, 1.0], [6, 4.0]]}])", kPath));
  // Its clearance fails first: within its radius of the wall.
  EXPECT_NE(e.find("w.json: people[0]: path: the person (radius 0.250000 m) touches wall"),
            std::string::npos)
      << e;
}

TEST(People, Issue16_TheGroundTruthListsThemAndLabelsTheirHits) {
  const std::filesystem::path dir = test::freshDir("people_gt");
  SimulatorOptions o;
  // From behind the robot, overtaking it in the next lane.
  const char* const overtaking = R"([{"waypoints": [[0.5, 0.8], [16, 0.8]], "speed_m_s": 1.0}])";
  o.world_file = test::writeText(dir / "w.json", corridorJson(overtaking, kPath));
  o.out_prefix = (dir / "run").string();
  o.cameras = false;
  o.progress = false;
  o.duration_s = 4.0;
  Simulator(o).run();
  const nlohmann::json gt = nlohmann::json::parse(test::readBytes(dir / "run.gt.json"));
  ASSERT_EQ(gt["people"].size(), 1u);
  const int id = gt["people"][0]["id"].get<int>();
  EXPECT_EQ(gt["people"][0]["kind"], "person");
  std::set<int> ids;
  for (const auto& scan : gt["structure_scans"]) {
    for (const auto& h : scan["hits"]) {
      ids.insert(h.get<int>());
    }
  }
  // The person passes the robot (0.4 m/s) at 1 m/s: the vertical laser sweeps it.
  EXPECT_EQ(ids.count(id), 1u);
}

}  // namespace
}  // namespace pmap::sim
