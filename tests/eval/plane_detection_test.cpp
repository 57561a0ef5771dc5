#include "pmap/eval/plane_detection.h"

#include <gtest/gtest.h>

#include <random>

namespace pmap::eval {
namespace {

/// n points on the plane z = z0 (or x = x0 when vertical), in a 2 m square.
void addSquare(std::vector<Eigen::Vector3d>& pts, std::vector<int>& label, int id, bool vertical,
               double at, int n, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0.0, 2.0);
  for (int i = 0; i < n; ++i) {
    const double a = u(rng);
    const double b = u(rng);
    pts.push_back(vertical ? Eigen::Vector3d(at, a, b) : Eigen::Vector3d(a, b, at));
    label.push_back(id);
  }
}

std::vector<int> range(int from, int to) {
  std::vector<int> r;
  for (int i = from; i < to; ++i) {
    r.push_back(i);
  }
  return r;
}

struct Cloud {
  std::vector<Eigen::Vector3d> pts;
  std::vector<int> label;
};

/// Plane 0: z = 0 (points 0-999), plane 1: x = 3 (1000-1999), no plane: x = 5 (2000-2499).
Cloud threeSquares() {
  Cloud c;
  std::mt19937 rng(7);
  addSquare(c.pts, c.label, 0, false, 0.0, 1000, rng);
  addSquare(c.pts, c.label, 1, true, 3.0, 1000, rng);
  addSquare(c.pts, c.label, kNoPlane, true, 5.0, 500, rng);
  return c;
}

TEST(PlaneScore, TheGroundTruthItselfScoresOne) {
  const Cloud c = threeSquares();
  const PlaneScore s = scorePlanes(c.pts, c.label, {range(0, 1000), range(1000, 2000)});
  EXPECT_EQ(s.detected, 2u);
  EXPECT_EQ(s.detected_matched, 2u);
  EXPECT_EQ(s.gt_planes, 2u);
  EXPECT_EQ(s.gt_matched, 2u);
  EXPECT_DOUBLE_EQ(s.f1, 1.0);
}

TEST(PlaneScore, ADetectionOnNoPlaneIsAFalsePositiveAndAMissedPlaneLowersRecall) {
  const Cloud c = threeSquares();
  const PlaneScore s = scorePlanes(c.pts, c.label, {range(0, 1000), range(2000, 2500)});
  EXPECT_DOUBLE_EQ(s.precision, 0.5);
  EXPECT_DOUBLE_EQ(s.recall, 0.5);
  EXPECT_EQ(s.missed, std::vector<int>{1});
  EXPECT_DOUBLE_EQ(s.f1, 0.5);
}

TEST(PlaneScore, AMatchNeedsHalfOfTheDetectionsPointsOnOnePlane) {
  Cloud c = threeSquares();
  std::mt19937 rng(11);
  addSquare(c.pts, c.label, kNoPlane, true, 3.0, 500,
            rng);  // 2500-2999: on plane 1's plane, unlabelled
  std::vector<int> d = range(1000, 1500);
  const std::vector<int> unlabelled = range(2500, 3000);
  d.insert(d.end(), unlabelled.begin(), unlabelled.end());
  EXPECT_EQ(scorePlanes(c.pts, c.label, {d}).detected_matched, 1u) << "50 % is enough";
  std::vector<int> less = range(1000, 1499);
  less.insert(less.end(), unlabelled.begin(), unlabelled.end());
  EXPECT_EQ(scorePlanes(c.pts, c.label, {less}).detected_matched, 0u) << "499 of 999 is not";
}

TEST(PlaneScore, ANormalMoreThan30DegreesOffIsNoMatch) {
  Cloud c = threeSquares();
  // A thin strip of plane 0 (x < 0.05) with a vertical strip beside it that
  // is no plane: 60 % on plane 0, but the fitted plane is vertical.
  std::vector<int> d;
  for (int i = 0; i < 1000; ++i) {
    if (c.pts[static_cast<std::size_t>(i)].x() < 0.05) {
      d.push_back(i);
    }
  }
  const std::size_t on_plane = d.size();
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0.0, 2.0);
  for (std::size_t k = 0; k < on_plane * 2 / 3; ++k) {
    c.pts.emplace_back(0.0, u(rng), u(rng));
    c.label.push_back(kNoPlane);
    d.push_back(static_cast<int>(c.pts.size()) - 1);
  }
  const PlaneScore s = scorePlanes(c.pts, c.label, {d});
  EXPECT_EQ(s.detected, 1u);
  EXPECT_EQ(s.detected_matched, 0u);
  PlaneScoreOptions wide;
  wide.max_angle_deg = 90;
  EXPECT_EQ(scorePlanes(c.pts, c.label, {d}, wide).detected_matched, 1u);
}

TEST(PlaneScore, APlaneSplitInTwoKeepsPrecisionAndCountsAsSplit) {
  const Cloud c = threeSquares();
  const PlaneScore s =
      scorePlanes(c.pts, c.label, {range(0, 500), range(500, 1000), range(1000, 2000)});
  EXPECT_EQ(s.detected_matched, 3u);
  EXPECT_EQ(s.gt_matched, 2u);
  EXPECT_EQ(s.gt_split, 1u);
  EXPECT_DOUBLE_EQ(s.f1, 1.0);
}

TEST(PlaneScore, SmallGroundTruthPlanesAreLeftOutOfRecall) {
  Cloud c = threeSquares();
  std::mt19937 rng(5);
  addSquare(c.pts, c.label, 2, false, 1.0, 50, rng);
  PlaneScoreOptions o;
  o.min_gt_points = 100;
  const PlaneScore s = scorePlanes(c.pts, c.label, {range(0, 1000), range(1000, 2000)}, o);
  EXPECT_EQ(s.gt_planes, 2u);
  EXPECT_DOUBLE_EQ(s.recall, 1.0);
  EXPECT_EQ(scorePlanes(c.pts, c.label, {range(0, 1000), range(1000, 2000)}).gt_planes, 3u);
}

TEST(PlaneScore, BadInputThrows) {
  const Cloud c = threeSquares();
  EXPECT_THROW(scorePlanes(c.pts, c.label, {{0, 1, 99999}}), std::invalid_argument);
  EXPECT_THROW(scorePlanes(c.pts, {0, 1}, {}), std::invalid_argument);
  PlaneScoreOptions o;
  o.min_share = 0;
  EXPECT_THROW(scorePlanes(c.pts, c.label, {}, o), std::invalid_argument);
  const PlaneScore none = scorePlanes({}, {}, {});
  EXPECT_EQ(none.detected, 0u);
  EXPECT_DOUBLE_EQ(none.f1, 0.0);
}

TEST(GroundTruthPlanes, CoplanarRectanglesAreOnePlaneWhicheverWayTheyFace) {
  GroundTruth gt;
  GtRectangle left;
  left.id = 1;
  left.corners = {Eigen::Vector3d(0, 2, 0), Eigen::Vector3d(1, 2, 0), Eigen::Vector3d(1, 2, 2),
                  Eigen::Vector3d(0, 2, 2)};
  GtRectangle right = left;  // beyond a door, facing the other way
  right.id = 2;
  right.corners = {Eigen::Vector3d(3, 2, 0), Eigen::Vector3d(3, 2, 2), Eigen::Vector3d(2, 2, 2),
                   Eigen::Vector3d(2, 2, 0)};
  GtRectangle recessed = left;  // a door 10 cm behind
  recessed.id = 3;
  for (auto& p : recessed.corners) {
    p.y() += 0.1;
  }
  GtCylinder bin;
  bin.id = 4;
  GtPoster poster;
  poster.id = 5;
  poster.wall_id = 2;
  gt.surfaces = {left, right, recessed};
  gt.cylinders = {bin};
  gt.posters = {poster};
  const std::vector<Eigen::Vector3d> pts(6, Eigen::Vector3d(0.5, 2, 1));
  const GtPlanes p = groundTruthPlanes(gt, pts, {1, 2, 3, 4, -1, 5});
  EXPECT_EQ(p.plane_of_point[0], p.plane_of_point[1]);
  EXPECT_NE(p.plane_of_point[0], p.plane_of_point[2]);
  EXPECT_EQ(p.plane_of_point[3], kNoPlane);
  EXPECT_EQ(p.plane_of_point[4], kNoPlane);
  EXPECT_EQ(p.plane_of_point[5], p.plane_of_point[1]) << "a poster is its wall";
  ASSERT_EQ(p.planes.size(), 2u);
  ASSERT_EQ(p.kinds.size(), 2u);
  EXPECT_NEAR(std::abs(p.planes[0][3]), 2.0, 1e-12);
}

TEST(GroundTruthPlanes, BoxPointsGetTheirNearestFace) {
  GroundTruth gt;
  GtBox desk;
  desk.id = 9;
  desk.centre = Eigen::Vector2d(4, 1);
  desk.yaw = 0.5;
  desk.min = Eigen::Vector3d(-0.8, -0.4, 0.0);
  desk.max = Eigen::Vector3d(0.8, 0.4, 0.75);
  gt.boxes = {desk};
  const double c = std::cos(0.5);
  const double s = std::sin(0.5);
  const auto world = [&](double x, double y, double z) {
    return Eigen::Vector3d(4 + c * x - s * y, 1 + s * x + c * y, z);
  };
  const std::vector<Eigen::Vector3d> pts = {world(0.1, 0.0, 0.751), world(-0.5, 0.2, 0.749),
                                            world(0.799, 0.0, 0.3), world(0.8, 0.3, 0.2)};
  const GtPlanes p = groundTruthPlanes(gt, pts, {9, 9, 9, 9});
  EXPECT_EQ(p.plane_of_point[0], p.plane_of_point[1]) << "both on the top";
  EXPECT_EQ(p.plane_of_point[2], p.plane_of_point[3]) << "both on the +x side";
  EXPECT_NE(p.plane_of_point[0], p.plane_of_point[2]);
  const Eigen::Vector4d top = p.planes[static_cast<std::size_t>(p.plane_of_point[0])];
  EXPECT_NEAR(top[2], 1.0, 1e-12);
  EXPECT_NEAR(top[3], 0.75, 1e-12);
  const Eigen::Vector4d side = p.planes[static_cast<std::size_t>(p.plane_of_point[2])];
  EXPECT_NEAR(side.head<3>().dot(world(0.8, 0.1, 0.5)), side[3], 1e-12);
}

}  // namespace
}  // namespace pmap::eval
