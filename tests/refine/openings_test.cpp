#include "pmap/refine/openings.h"

#include <gtest/gtest.h>

#include <random>

#include "refine_world.h"

namespace pmap::refine {
namespace {

using testing::rectangle;
using V = Eigen::Vector3d;

// A wall (plane y = 0, x in [0, 4], z in [0.3, 2.7]) scanned by vertical
// scans every 8 cm along x, beams every 2.5 cm in z, from a sensor at
// y = 1.2; an opening x in [1.55, 2.45], z up to 2.05 holds a door `depth`
// behind the wall (y = -depth; negative: a cabinet front standing proud of
// the wall). The EM's door rectangle is the tight box of its points.
struct DoorScene {
  std::vector<V> points, viewpoints;
  std::vector<std::int32_t> assignment;
  std::vector<em::Surface> surfaces;

  explicit DoorScene(double depth, double sigma = 0.0) {
    std::mt19937 rng(5);
    std::normal_distribution<double> noise(0.0, sigma);
    double x0 = INFINITY, x1 = -INFINITY, z1 = -INFINITY;
    for (int scan = 0; scan * 0.08 <= 4.0 + 1e-9; ++scan) {
      const double x = scan * 0.08;
      for (int beam = 0; 0.3 + beam * 0.025 <= 2.7 + 1e-9; ++beam) {
        const double z = 0.3 + beam * 0.025;
        const bool door = x > 1.55 && x < 2.45 && z < 2.05;
        points.emplace_back(x, (door ? -depth : 0.0) + noise(rng), z);
        viewpoints.emplace_back(x, 1.2, 0.3);
        assignment.push_back(door ? 1 : 0);
        if (door) {
          x0 = std::min(x0, x), x1 = std::max(x1, x), z1 = std::max(z1, z);
        }
      }
    }
    const V y = V::UnitY();
    surfaces.push_back({rectangle(y, {2.0, 0.0, 1.5}, V::UnitX(), 2.0, 1.2), 10, 0, false});
    surfaces.push_back({rectangle(y, {0.5 * (x0 + x1), -depth, 0.5 * (0.3 + z1)}, V::UnitX(),
                                  0.5 * (x1 - x0), 0.5 * (z1 - 0.3)),
                        11, 0, false});
  }
  const em::Rectangle& door() const { return surfaces[1].rect; }
};

TEST(Openings, ARecessedDoorEndsHalfwayBetweenItsPointsAndTheWalls) {
  for (const double sigma : {0.0, 0.005}) {
    DoorScene s(0.1, sigma);
    const em::Rectangle wall_before = s.surfaces[0].rect;
    const OpeningResult r =
        alignToOpenings(s.points, s.assignment, s.viewpoints, RefineOptions{}, s.surfaces);
    ASSERT_EQ(r.openings.size(), 1u) << sigma;
    EXPECT_EQ(r.openings[0].door_id, 11);
    EXPECT_EQ(r.openings[0].wall_id, 10);
    EXPECT_EQ(r.openings[0].edges, 3);  // the sides and the top; the foot has no wall below
    const em::Rectangle& d = s.door();
    // The door's points span x in [1.60, 2.40], the wall's next scans are at
    // 1.52 and 2.48: the edges go halfway, 1 cm from the true 1.55 / 2.45.
    EXPECT_NEAR(d.centre.x() - d.half_u, 1.56, 1e-6);
    EXPECT_NEAR(d.centre.x() + d.half_u, 2.44, 1e-6);
    EXPECT_NEAR(d.centre.z() + d.half_v, 2.05, 0.0125 + 1e-6);  // half a beam step
    EXPECT_NEAR(d.centre.z() - d.half_v, 0.3, 1e-9);
    // The door keeps its plane; the wall is untouched.
    EXPECT_NEAR(d.centre.y(), -0.1, 1e-12);
    EXPECT_EQ(s.surfaces[0].rect.centre, wall_before.centre);
    EXPECT_EQ(s.surfaces[0].rect.half_u, wall_before.half_u);
  }
}

TEST(Openings, AFrontStandingProudOfTheWallOrTooFarBehindItIsLeftAlone) {
  for (const double depth : {-0.1, 0.5}) {
    DoorScene s(depth);
    const em::Rectangle before = s.door();
    EXPECT_TRUE(alignToOpenings(s.points, s.assignment, s.viewpoints, RefineOptions{}, s.surfaces)
                    .openings.empty())
        << depth;
    EXPECT_EQ(s.door().half_u, before.half_u);
    EXPECT_EQ(s.door().centre, before.centre);
  }
}

TEST(Openings, WithoutViewpointsNothingMoves) {
  DoorScene s(0.1);
  EXPECT_TRUE(
      alignToOpenings(s.points, s.assignment, {}, RefineOptions{}, s.surfaces).openings.empty());
  EXPECT_TRUE(alignToOpenings({}, {}, {}, RefineOptions{}, s.surfaces).openings.empty());
}

}  // namespace
}  // namespace pmap::refine
