#include "pmap/eval/seam_gaps.h"

#include <gtest/gtest.h>

#include "surface_test_world.h"

namespace pmap::eval {
namespace {

using testing::rectangle;
using V = Eigen::Vector3d;

// A corridor corner: wall 1 (y = 0), ceiling 2 (z = 2.7) over the corridor
// (y in [0, 2]), end wall 3 (x = 4), and wall 4 beyond the end (x in [4, 6],
// y = 2) that touches the ceiling's corner only.
GroundTruth corridor() {
  testing::SurfaceTestWorld w;
  w.addRectangle(1, "wall", rectangle(V(0, 0, 0), V(4, 0, 0), V(0, 0, 2.7)));
  w.addRectangle(2, "ceiling", rectangle(V(0, 0, 2.7), V(0, 2, 0), V(4, 0, 0)));
  w.addRectangle(3, "wall", rectangle(V(4, 0, 0), V(0, 2, 0), V(0, 0, 2.7)));
  w.addRectangle(4, "wall", rectangle(V(4, 2, 0), V(2, 0, 0), V(0, 0, 2.7)));
  return w.gt;
}

MapSurface mapSurfaceOf(const GtRectangle& r, int id) {
  MapSurface s;
  s.id = id;
  s.normal = r.normal;
  s.offset_m = r.normal.dot(r.corners[0]);
  s.corners = r.corners;
  return s;
}

TEST(GroundTruthSeams, SharedEdgesOfNonParallelSurfaces) {
  const GroundTruth gt = corridor();
  const auto seams = groundTruthSeams(gt, {1, 2, 3, 4});
  auto has = [&](int a, int b) {
    for (const GtSeam& s : seams) {
      if (s.gt_id == a && s.gt_other == b)
        return true;
    }
    return false;
  };
  EXPECT_TRUE(has(1, 2));  // wall under the ceiling
  EXPECT_TRUE(has(2, 1));
  EXPECT_TRUE(has(1, 3));  // corner of two walls
  EXPECT_TRUE(has(3, 1));
  EXPECT_TRUE(has(2, 3));
  EXPECT_TRUE(has(3, 2));
  EXPECT_FALSE(has(2, 4));  // touching at a corner point is not a seam
  EXPECT_FALSE(has(4, 2));
  EXPECT_FALSE(has(1, 4));           // parallel
  EXPECT_EQ(seams.size(), 6u + 2u);  // and walls 3 and 4 meet at x = 4, y = 2
}

TEST(SeamSides, ExactMapHasNoGaps) {
  const GroundTruth gt = corridor();
  std::vector<std::pair<int, MapSurface>> primary;
  for (const GtRectangle& r : gt.surfaces)
    primary.emplace_back(r.id, mapSurfaceOf(r, 10 + r.id));
  const auto sides = seamSides(gt, primary);
  EXPECT_EQ(sides.size(), 8u);
  for (const SeamSide& s : sides) {
    EXPECT_NEAR(s.gap_m, 0.0, 1e-9) << s.gt_id << " " << s.gt_other;
    EXPECT_EQ(s.map_id, 10 + s.gt_id);
  }
}

TEST(SeamSides, GapIsPositiveShortOfTheSeamAndNegativeBeyondIt) {
  const GroundTruth gt = corridor();
  std::vector<std::pair<int, MapSurface>> primary;
  for (const GtRectangle& r : gt.surfaces)
    primary.emplace_back(r.id, mapSurfaceOf(r, r.id));
  // The wall stops 5 cm under the ceiling; the ceiling overshoots the end
  // wall by 3 cm.
  MapSurface& wall = primary[0].second;
  wall.corners[2].z() -= 0.05;
  wall.corners[3].z() -= 0.05;
  MapSurface& ceiling = primary[1].second;
  ceiling.corners[2].x() += 0.03;
  ceiling.corners[3].x() += 0.03;
  for (const SeamSide& s : seamSides(gt, primary)) {
    if (s.gt_id == 1 && s.gt_other == 2) {
      EXPECT_NEAR(s.gap_m, 0.05, 1e-9);
    }
    if (s.gt_id == 2 && s.gt_other == 3) {
      EXPECT_NEAR(s.gap_m, -0.03, 1e-9);
    }
    if (s.gt_id == 2 && s.gt_other == 1) {
      EXPECT_NEAR(s.gap_m, 0.0, 1e-9);
    }
  }
}

TEST(SeamSides, UnmatchedSurfacesHaveNoSides) {
  const GroundTruth gt = corridor();
  std::vector<std::pair<int, MapSurface>> primary = {{1, mapSurfaceOf(gt.surfaces[0], 1)}};
  EXPECT_TRUE(seamSides(gt, primary).empty());
}

// A door in a wall: its top and sides bound the wall's opening, its foot on
// the floor does not; a rectangle without a parent, or one not parallel to
// it, has no opening edges.
TEST(OpeningEdges, ADoorsTopAndSidesButNotItsFoot) {
  testing::SurfaceTestWorld w;
  w.addRectangle(1, "wall", rectangle(V(0, 0, 0), V(6, 0, 0), V(0, 0, 2.7)));
  w.addRectangle(2, "door", rectangle(V(2, -0.1, 0), V(0.9, 0, 0), V(0, 0, 2.0)));
  w.gt.surfaces.back().parent = 1;
  w.addRectangle(3, "wall", rectangle(V(6, 0, 0), V(0, 2, 0), V(0, 0, 2.7)));
  w.gt.surfaces.back().parent = 1;  // perpendicular: no opening
  const auto edges = openingEdges(w.gt, {1, 2, 3});
  ASSERT_EQ(edges.size(), 3u);
  for (const GtSeam& e : edges) {
    EXPECT_EQ(e.gt_id, 2);
    EXPECT_EQ(e.gt_other, 1);
    EXPECT_NE(e.edge, 0);  // edge 0 joins (2, -0.1, 0) and (2.9, -0.1, 0): the foot
  }
  // The door's clipped reference (what the laser saw: 8 cm short of the
  // jambs, from 0.3 m up) closes to the opening, not down to the floor.
  const GtRectangle& door = w.gt.surfaces[1];
  const std::array<Eigen::Vector3d, 4> clipped = {V(2.08, -0.1, 0.3), V(2.82, -0.1, 0.3),
                                                  V(2.82, -0.1, 1.97), V(2.08, -0.1, 1.97)};
  const auto closed = closedReference(door, clipped, edges, 0.3);
  EXPECT_LT((closed[0] - V(2.0, -0.1, 0.3)).norm(), 1e-12);
  EXPECT_LT((closed[2] - V(2.9, -0.1, 2.0)).norm(), 1e-12);
}

}  // namespace
}  // namespace pmap::eval

namespace pmap::eval {
namespace {

TEST(ClosedReference, SeenEdgesNearASharedEdgeAreClosedOthersStay) {
  const GroundTruth gt = corridor();
  const GtRectangle& wall = gt.surfaces[0];  // corners (0,0,0) (4,0,0) (4,0,2.7) (0,0,2.7)
  // The laser saw x in [0.2, 3.8], z in [0.3, 2.62].
  const std::array<Eigen::Vector3d, 4> clipped = {V(0.2, 0, 0.3), V(3.8, 0, 0.3), V(3.8, 0, 2.62),
                                                  V(0.2, 0, 2.62)};
  const auto seams = groundTruthSeams(gt, {1, 2, 3});
  const auto closed = closedReference(wall, clipped, seams, 0.3);
  // Top edge (edge 2, under the ceiling) and the end at x = 4 (edge 1, wall 3) close.
  EXPECT_LT((closed[1] - V(4.0, 0, 0.3)).norm(), 1e-12);
  EXPECT_LT((closed[2] - V(4.0, 0, 2.7)).norm(), 1e-12);
  EXPECT_LT((closed[3] - V(0.2, 0, 2.7)).norm(), 1e-12);
  // The floor (not seen) and the open end at x = 0 stay clipped.
  EXPECT_LT((closed[0] - V(0.2, 0, 0.3)).norm(), 1e-12);
  // Beyond the reach nothing moves.
  const auto far = closedReference(wall, clipped, seams, 0.05);
  EXPECT_LT((far[1] - clipped[1]).norm(), 1e-12);
  EXPECT_LT((far[2] - clipped[2]).norm(), 1e-12);
}

}  // namespace
}  // namespace pmap::eval
