#include "pmap/sim/world_builder.h"

#include <gtest/gtest.h>

#include <set>

#include "pmap/common/error.h"
#include "pmap/sim/ray_caster.h"
#include "pmap/sim/rng.h"
#include "pmap/sim/trajectory.h"
#include "pmap/sim/world_loader.h"

namespace pmap::sim {
namespace {

using Eigen::Vector3d;

World buildJson(const std::string& json) {
  return buildWorld(parseWorldText(json, "w.json"));
}

World bundled(const std::string& name) {
  return buildWorld(
      loadWorldFile(std::string(PMAP_SOURCE_DIR) + "/config/worlds/" + name + ".json"));
}

/// An L: 10 m along +x, then 6 m along +y (left turn), 2 m wide, 2.5 m high.
const char* kL = R"({"name": "L", "corridors": [{"centreline": [[0, 0], [10, 0], [10, 6]],
  "width_m": 2.0, "height_m": 2.5%s}], "path": {"waypoints": [[1, 0], [9, 0]]}})";

std::string lWith(const std::string& inner) {
  char buf[1024];
  std::snprintf(buf, sizeof(buf), kL, inner.c_str());
  return buf;
}

bool hasCorner(const Surface& s, const Vector3d& p) {
  for (const Vector3d& c : s.rect.corners()) {
    if ((c - p).norm() < 1e-9) {
      return true;
    }
  }
  return false;
}

int countWallsWithCorner(const World& w, const Vector3d& p) {
  int n = 0;
  for (const Surface& s : w.surfaces) {
    n += (s.kind == "wall" && hasCorner(s, p)) ? 1 : 0;
  }
  return n;
}

TEST(WorldBuilder, LCorridorWallsMeetAtTheCorners) {
  const World w = buildJson(lWith(""));
  // 2 walls + floor + ceiling per leg, 2 end walls.
  EXPECT_EQ(w.surfaces.size(), 10u);
  // Outer corner (11, -1) and inner corner (9, 1), at floor and ceiling height.
  for (const double z : {0.0, 2.5}) {
    EXPECT_EQ(countWallsWithCorner(w, Vector3d(11, -1, z)), 2);
    EXPECT_EQ(countWallsWithCorner(w, Vector3d(9, 1, z)), 2);
  }
  // The corner square belongs to the first leg: floors tile without overlap.
  double floor_area = 0.0;
  for (const Surface& s : w.surfaces) {
    if (s.kind == "floor") {
      floor_area += s.rect.length_u * s.rect.length_v;
      EXPECT_NEAR(s.rect.normal().z(), 1.0, 1e-12);
    }
    if (s.kind == "ceiling") {
      EXPECT_NEAR(s.rect.normal().z(), -1.0, 1e-12);
    }
  }
  EXPECT_NEAR(floor_area, 11.0 * 2.0 + 5.0 * 2.0, 1e-9);
}

TEST(WorldBuilder, DoorIsAHoleWithARecessedLeafAndJambs) {
  const World w = buildJson(lWith(R"(, "doors": [{"leg": 0, "side": "right", "centre_m": 4.0,
      "width_m": 0.9, "height_m": 2.0}])"));
  const Surface* door = nullptr;
  for (const Surface& s : w.surfaces) {
    door = s.kind == "door" ? &s : door;
  }
  ASSERT_NE(door, nullptr);
  ASSERT_GE(door->parent_id, 0);
  const Surface& wall = w.surfaces[static_cast<std::size_t>(door->parent_id)];
  EXPECT_EQ(wall.kind, "wall");
  ASSERT_EQ(wall.rect.holes.size(), 1u);
  // Door leaf 0.10 m behind the wall plane, facing the same way.
  for (const Vector3d& c : door->rect.corners()) {
    EXPECT_NEAR(wall.rect.normal().dot(c - wall.rect.origin), -0.10, 1e-12);
    EXPECT_NEAR(c.y(), -1.10, 1e-12);
  }
  EXPECT_TRUE(door->rect.normal().isApprox(wall.rect.normal()));
  // The hole spans exactly the door's extent in the wall plane.
  const auto hole = wall.rect.holeCorners(wall.rect.holes[0]);
  for (const Vector3d& h : hole) {
    EXPECT_NEAR(h.y(), -1.0, 1e-12);
    EXPECT_TRUE(std::abs(h.x() - 3.55) < 1e-9 || std::abs(h.x() - 4.45) < 1e-9);
    EXPECT_TRUE(std::abs(h.z()) < 1e-9 || std::abs(h.z() - 2.0) < 1e-9);
  }
  int jambs = 0;
  int thresholds = 0;
  for (const Surface& s : w.surfaces) {
    if (s.parent_id == wall.id && s.kind != "door") {
      EXPECT_NEAR(std::min(s.rect.length_u, s.rect.length_v), 0.10, 1e-12);
      jambs += s.kind == "jamb" ? 1 : 0;
      thresholds += s.kind == "floor" ? 1 : 0;
    }
  }
  EXPECT_EQ(jambs, 3);       // two sides and a head
  EXPECT_EQ(thresholds, 1);  // the reveal's floor
  // A beam through the opening hits the leaf at 1.1 m (wall at 1.0 m + recess).
  const RayCaster caster(w);
  const auto hit = caster.cast(Vector3d(4.0, 0.0, 1.0), Vector3d(0, -1, 0), 30.0);
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->id, door->id);
  EXPECT_NEAR(hit->t, 1.10, 1e-12);
}

TEST(WorldBuilder, IdsAreUniqueAcrossSurfacesClutterAndPosters) {
  const World w = bundled("default");
  std::set<int> ids;
  for (const Surface& s : w.surfaces) {
    EXPECT_TRUE(ids.insert(s.id).second);
  }
  for (const Clutter& c : w.clutter) {
    EXPECT_TRUE(ids.insert(c.id).second);
  }
  for (const Poster& p : w.posters) {
    EXPECT_TRUE(ids.insert(p.id).second);
    EXPECT_EQ(w.surfaces[static_cast<std::size_t>(p.wall_index)].id, p.wall_id);
    EXPECT_EQ(w.surfaces[static_cast<std::size_t>(p.wall_index)].kind, "wall");
  }
  EXPECT_EQ(ids.size(), w.surfaces.size() + w.clutter.size() + w.posters.size());
  EXPECT_EQ(w.posters.size(), 2u);
  EXPECT_EQ(w.clutter.size(), 2u);
}

TEST(WorldBuilder, PostersLieFlushOnTheirWall) {
  const World w = bundled("default");
  for (const Poster& p : w.posters) {
    const Surface& wall = w.surfaces[static_cast<std::size_t>(p.wall_index)];
    EXPECT_TRUE(p.rect.normal().isApprox(wall.rect.normal()));
    EXPECT_NEAR(p.rect.axis_v.z(), 1.0, 1e-12);  // image rows run downwards
    for (const Vector3d& c : p.rect.corners()) {
      EXPECT_NEAR(wall.rect.normal().dot(c - wall.rect.origin), 0.0, 1e-12);
      const Eigen::Vector2d l = wall.rect.toLocal(c);
      EXPECT_TRUE(wall.rect.containsLocal(l.x(), l.y()));
    }
  }
}

TEST(WorldBuilder, SlopedCeilingGivesWallsOfDifferentHeights) {
  const World w = buildJson(R"({"name": "s", "corridors": [{"centreline": [[0, 0], [10, 0]],
    "width_m": 2.0, "height_m": 2.5, "legs": [{"ceiling_slope_deg": 10}]}],
    "path": {"waypoints": [[1, 0], [9, 0]]}})");
  double left = 0.0;
  double right = 0.0;
  for (const Surface& s : w.surfaces) {
    if (s.kind == "wall" && std::abs(s.rect.normal().y()) > 0.5) {
      (s.rect.origin.y() > 0 ? left : right) = s.rect.length_v;
    }
  }
  EXPECT_NEAR(right, 2.5, 1e-12);
  EXPECT_NEAR(left, 2.5 + 2.0 * std::tan(10.0 * M_PI / 180.0), 1e-12);
  const RayCaster caster(w);
  const auto up = caster.cast(Vector3d(5, 0, 1), Vector3d(0, 0, 1), 30.0);
  ASSERT_TRUE(up);
  EXPECT_NEAR(up->t, 1.5 + std::tan(10.0 * M_PI / 180.0), 1e-9);
}

TEST(WorldBuilder, GeometryErrorsNameTheElement) {
  auto errorOf = [](const std::string& json) {
    try {
      buildJson(json);
    } catch (const ConfigError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  const std::string off = errorOf(lWith(R"(, "doors": [{"leg": 1, "side": "left",
      "centre_m": 5.8, "width_m": 0.9, "height_m": 2.0}])"));
  EXPECT_NE(off.find("corridors[0].doors[0]: does not fit"), std::string::npos) << off;
  const std::string overlap = errorOf(lWith(R"(, "doors": [
      {"leg": 0, "side": "left", "centre_m": 4.0, "width_m": 0.9, "height_m": 2.0},
      {"leg": 0, "side": "left", "centre_m": 4.5, "width_m": 0.9, "height_m": 2.0}])"));
  EXPECT_NE(overlap.find("doors[1]: overlaps"), std::string::npos) << overlap;
  const std::string poster = errorOf(lWith(R"(, "doors": [
      {"leg": 0, "side": "left", "centre_m": 4.0, "width_m": 0.9, "height_m": 2.0}],
      "posters": [{"leg": 0, "side": "left", "centre_m": 4.5, "bottom_m": 1.0}])"));
  EXPECT_NE(poster.find("posters[0]: overlaps"), std::string::npos) << poster;
  const std::string tall = errorOf(lWith(R"(, "doors": [
      {"leg": 0, "side": "left", "centre_m": 4.0, "width_m": 0.9, "height_m": 2.6}])"));
  EXPECT_NE(tall.find("reaches the top"), std::string::npos) << tall;
  EXPECT_NE(errorOf(R"({"name": "t", "corridors": [{"centreline": [[0, 0], [10, 0], [15, 5]]}],
      "path": {"waypoints": [[1, 0], [9, 0]]}})")
                .find("not +-90 degrees"),
            std::string::npos);
  EXPECT_NE(errorOf(R"({"name": "t", "corridors": [{"centreline": [[0, 0], [10, 0], [10, 1],
      [20, 1]]}], "path": {"waypoints": [[1, 0], [9, 0]]}})")
                .find("shorter than"),
            std::string::npos);
}

/// From points along the path, rays in every direction must hit something:
/// the expanded world has no gaps at corners, openings, slopes or rooms.
void expectClosed(const World& world) {
  const RayCaster caster(world);
  const Trajectory traj(world.path, world.source_file);
  Rng rng(3);
  for (double s = 0.0; s <= traj.length_m(); s += 0.5) {
    const Pose2D p = traj.poseAtDistance(s);
    for (int i = 0; i < 200; ++i) {
      const Vector3d o(p.x, p.y, rng.uniform(0.05, 2.4));
      Vector3d d(rng.normal(), rng.normal(), rng.normal());
      d.normalize();
      const auto hit = caster.cast(o, d, 200.0);
      ASSERT_TRUE(hit) << world.name << ": ray escapes from " << o.transpose() << " along "
                       << d.transpose();
      ASSERT_LT(d.dot(hit->normal), 0.0)
          << world.name << ": surface " << hit->id << " seen from behind";
    }
  }
}

TEST(WorldBuilder, BundledWorldsAreClosedAndFaceTheRobot) {
  for (const char* name : {"default", "second", "office", "long"}) {
    expectClosed(bundled(name));
  }
}

}  // namespace
}  // namespace pmap::sim
