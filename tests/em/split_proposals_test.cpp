#include "pmap/em/split_proposals.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <random>

#include "em_test_worlds.h"
#include "pmap/em/surface_fit.h"

namespace pmap::em {
namespace {

using testing::allIndices;

// A wall with a door 10 cm behind it (noise 2 cm).
struct RecessedDoor {
  testing::Cloud cloud;
  std::vector<std::int32_t> door;
  Rectangle rect;
  RecessedDoor(double depth, double noise, double step = 0.03) {
    testing::CorridorSpec s;
    s.step = step;
    s.length = 4.0;
    s.height = 2.5;
    s.door_depth = depth;
    s.sigma = noise;
    s.ceiling = false;
    std::mt19937_64 rng(5);
    testing::Cloud all;
    testing::addCorridor(all, s, rng);
    std::vector<std::int32_t> wall;
    for (std::size_t i = 0; i < all.points.size(); ++i) {
      if (all.points[i].y() < 0.5) {  // the left wall only
        const Eigen::Vector3d& p = all.points[i];
        const bool in_door = p.x() >= s.door_x0 && p.x() <= s.door_x1 && p.z() < s.door_height;
        (in_door ? door : wall).push_back(static_cast<std::int32_t>(cloud.points.size()));
        cloud.points.push_back(p);
      }
    }
    // The wall's plane (as EM finds it once the door is a surface of its
    // own), spanning wall and door.
    EXPECT_EQ(fitSurface(cloud.points, wall, rect), FitStatus::kOk);
    Rectangle span = rect;
    EXPECT_EQ(fitRectangle(cloud.points, allIndices(cloud.points.size()), span), FitStatus::kOk);
    rect = span;
  }
};

// ~25 points per 15 cm cell. (At 5 cm sampling, ~9 per cell, the jitter
// leaves cells under the 8-point minimum, which cut the door's flagged cells
// into pieces: the part is then only the largest piece, see below.)
TEST(ResidualSplit, APatchTenCentimetresBehindIsSplitOff) {
  for (const double sigma : {0.02, 0.05}) {
    const RecessedDoor w(0.10, 0.02);
    const auto p = residualSplit(w.cloud.points, allIndices(w.cloud.points.size()), w.rect, 0.15,
                                 0.04, sigma, 60);
    ASSERT_TRUE(p.has_value()) << "sigma " << sigma;
    // part_a is the patch: most door points, few wall points (those sharing
    // a 15 cm cell with the door along its edges, which cells do not follow).
    std::size_t door_in_a = 0;
    for (const std::int32_t i : p->part_a) {
      door_in_a += std::binary_search(w.door.begin(), w.door.end(), i) ? 1 : 0;
    }
    EXPECT_GT(door_in_a, 0.85 * w.door.size());
    EXPECT_LT(p->part_a.size() - door_in_a, 0.1 * p->part_a.size());
    EXPECT_EQ(p->part_a.size() + p->part_b.size(), w.cloud.points.size());
  }
}

TEST(ResidualSplit, AtSparseSamplingThePatchIsStillProposedInPart) {
  const RecessedDoor w(0.10, 0.02, 0.05);
  const auto p = residualSplit(w.cloud.points, allIndices(w.cloud.points.size()), w.rect, 0.15,
                               0.04, 0.02, 60);
  ASSERT_TRUE(p.has_value());
  std::size_t door_in_a = 0;
  for (const std::int32_t i : p->part_a) {
    door_in_a += std::binary_search(w.door.begin(), w.door.end(), i) ? 1 : 0;
  }
  std::cout << "5 cm sampling: the residual part holds " << door_in_a << " of " << w.door.size()
            << " door points (" << p->part_a.size() - door_in_a << " wall points)\n";
  EXPECT_GE(door_in_a, 60u);
  EXPECT_LT(p->part_a.size() - door_in_a, 0.05 * p->part_a.size());
}

TEST(ResidualSplit, AFlatWallOrAShallowPatchIsNotSplit) {
  const RecessedDoor flat(0.0, 0.02);
  const auto all = allIndices(flat.cloud.points.size());
  EXPECT_FALSE(residualSplit(flat.cloud.points, all, flat.rect, 0.15, 0.04, 0.02, 60));
  const RecessedDoor shallow(0.02, 0.005);  // 2 cm: below split_min_offset_m
  EXPECT_FALSE(residualSplit(shallow.cloud.points, allIndices(shallow.cloud.points.size()),
                             shallow.rect, 0.15, 0.04, 0.005, 60));
  // Fewer than two parts' worth of members.
  const RecessedDoor door(0.10, 0.02);
  EXPECT_FALSE(
      residualSplit(door.cloud.points, door.door, door.rect, 0.15, 0.04, 0.02, door.door.size()));
  EXPECT_FALSE(residualSplit(door.cloud.points, {}, door.rect, 0.15, 0.04, 0.02, 3));
}

// A stray member on the wall's plane 1e9 or 1e12 m away (a mis-placed scan)
// stretches the rectangle: the grid stays one cell per occupied cell, so the
// test runs in the members' memory and finds no patch in the coarse cells.
TEST(ResidualSplit, Item12_AStretchedRectangleCostsTheMembersNotTheExtent) {
  for (const double far_m : {1e9, 1e12}) {
    RecessedDoor w(0.10, 0.02);
    const Eigen::Vector3d u = w.rect.axis_u;
    const Eigen::Vector3d corner = w.rect.centre - u * w.rect.half_u;
    w.cloud.points.push_back(corner + u * far_m);
    w.cloud.points.push_back(corner + u * far_m + w.rect.axisV() * 0.5);
    Rectangle stretched = w.rect;
    stretched.half_u = 0.5 * far_m;
    stretched.centre = corner + u * stretched.half_u;
    const auto all = allIndices(w.cloud.points.size());
    const auto splits = residualSplits(w.cloud.points, all, stretched, 0.15, 0.04, 0.02, 60);
    for (const SplitProposal& p : splits) {
      EXPECT_EQ(p.part_a.size() + p.part_b.size(), all.size());
    }
    // The members' own rectangle still finds the door.
    EXPECT_TRUE(residualSplit(w.cloud.points, all, w.rect, 0.15, 0.04, 0.02, 60).has_value());
  }
}

}  // namespace
}  // namespace pmap::em
