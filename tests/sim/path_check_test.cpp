#include "pmap/sim/path_check.h"

#include <gtest/gtest.h>

#include "pmap/common/error.h"
#include "pmap/sim/world_builder.h"
#include "pmap/sim/world_loader.h"

namespace pmap::sim {
namespace {

World corridorWithPath(const std::string& waypoints, const std::string& clutter = "[]") {
  return buildWorld(parseWorldText(
      R"({"name": "p", "corridors": [{"centreline": [[0, 0], [10, 0]], "width_m": 2.0}],
          "clutter": )" +
          clutter + R"(, "path": {"waypoints": )" + waypoints + "}}",
      "w.json"));
}

void check(const World& w) {
  const RayCaster caster(w);
  const Trajectory t(w.path, w.source_file);
  checkPathClearance(caster, t, w.path.robot_radius_m, w.source_file);
}

TEST(PathCheck, AcceptsAPathInsideTheCorridor) {
  EXPECT_NO_THROW(check(corridorWithPath("[[1, 0.1], [9, 0.1]]")));
}

TEST(PathCheck, RejectsDrivingThroughAWall) {
  try {
    check(corridorWithPath("[[1, 0], [9, 3]]"));
    FAIL() << "expected a ConfigError";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("w.json: path:"), std::string::npos) << e.what();
  }
}

TEST(PathCheck, RejectsGrazingABin) {
  EXPECT_THROW(check(corridorWithPath("[[1, 0], [9, 0]]",
                                      R"([{"kind": "bin", "centre": [5, 0.4], "radius_m": 0.2,
                                  "z_max_m": 1.0}])")),
               ConfigError);
  EXPECT_THROW(check(corridorWithPath("[[0.1, 0], [9, 0]]")), ConfigError);  // end wall
}

TEST(PathCheck, BundledWorldsPass) {
  for (const char* name : {"default", "second", "office", "long"}) {
    const World w = buildWorld(
        loadWorldFile(std::string(PMAP_SOURCE_DIR) + "/config/worlds/" + name + ".json"));
    EXPECT_NO_THROW(check(w)) << name;
  }
}

}  // namespace
}  // namespace pmap::sim
