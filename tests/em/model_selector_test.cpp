#include "pmap/em/model_selector.h"

#include <gtest/gtest.h>

#include "em_test_worlds.h"
#include "pmap/em/surface_fit.h"

namespace pmap::em {
namespace {

using testing::allIndices;

struct World {
  testing::Cloud cloud;
  Neighbours neighbours;
  void done() { neighbours = cloud.neighbours(); }
};

// A wall y = 0, 4 m x 2.5 m, one scan per 5 cm of x.
World wall(double door_depth = 0.0) {
  World w;
  testing::CorridorSpec s;
  s.length = 4.0;
  s.ceiling = false;
  s.door_depth = door_depth;
  std::mt19937_64 rng(1);
  testing::addCorridor(w.cloud, s, rng);
  // Keep the left wall: its beams are the first height / step = 50 cols.
  testing::Cloud left;
  for (std::size_t i = 0; i < w.cloud.points.size(); ++i) {
    if (w.cloud.keys[i].col < 50) {
      left.points.push_back(w.cloud.points[i]);
      left.keys.push_back(w.cloud.keys[i]);
      left.rows.push_back(w.cloud.rows[i]);
    }
  }
  w.cloud = left;
  w.done();
  return w;
}

Surface fittedOn(const World& w, const std::vector<std::int32_t>& members) {
  Surface s;
  s.rect.normal = {0, 1, 0};
  EXPECT_EQ(fitSurface(w.cloud.points, members, s.rect), FitStatus::kOk);
  return s;
}

TEST(ModelSelector, ExpectIsTheEStepWithTheCutoffIndex) {
  const World w = wall();
  PlanarEmOptions o;
  const ModelSelector sel(w.cloud.points, w.neighbours, w.cloud.rows, o);
  const MeasurementModel m(o.sigma_m, o.z_max_m);
  EXPECT_DOUBLE_EQ(sel.cutoff(), m.cutoffDistance(o.responsibility_tolerance));
  const std::vector<Surface> s = {fittedOn(w, allIndices(w.cloud.points.size()))};
  Responsibilities a, b;
  sel.expect(s, a);
  computeResponsibilities(w.cloud.points, s, RectangleIndex(s, sel.cutoff()), m,
                          o.responsibility_tolerance, 1, b);
  EXPECT_EQ(a.weight, b.weight);
  EXPECT_EQ(a.best, b.best);
  EXPECT_EQ(a.total_loglik, b.total_loglik);
}

TEST(ModelSelector, ARoundSeedsAWallFromNothing) {
  const World w = wall();
  const PlanarEmOptions o;
  ModelSelector sel(w.cloud.points, w.neighbours, w.cloud.rows, o);
  std::vector<Surface> s;
  std::int32_t next_id = 0;
  const SelectionChanges c = sel.round(s, next_id);
  EXPECT_EQ(c.added, 1);
  EXPECT_TRUE(c.any());
  ASSERT_EQ(s.size(), 1u);
  EXPECT_EQ(s[0].id, 0);
  EXPECT_EQ(next_id, 1);
  EXPECT_LT(testing::lineAngleDeg(s[0].rect.normal, Eigen::Vector3d::UnitY()), 1.0);
  EXPECT_NEAR(s[0].rect.planeDistance({1, 0, 1}), 0.0, 0.01);
}

// The visible effect of the seeding bug (see seeding_test.cpp,
// Seeding.ASeededSurfaceIsTheFitOfItsMembers; libs/em/src/seeding.cpp): the
// wall (4050 points) is seeded as a rectangle over the first 2048 points of
// its outlier band (about 6.3 m^2 of 9.8), and the next round seeds two more
// surfaces on the rest of the same wall, which a later round fuses again.
// With the band grown on a copy, the first round gives the whole wall and the
// second changes nothing.
TEST(ModelSelector, ASeededWallCoversTheWallAndTheNextRoundIsQuiet) {
  const World w = wall();
  ModelSelector sel(w.cloud.points, w.neighbours, w.cloud.rows, PlanarEmOptions{});
  std::vector<Surface> s;
  std::int32_t next_id = 0;
  sel.round(s, next_id);
  ASSERT_EQ(s.size(), 1u);
  EXPECT_NEAR(s[0].rect.area(), 4.0 * 2.45, 0.3);
  EXPECT_FALSE(sel.round(s, next_id).any());
  EXPECT_EQ(s.size(), 1u);
}

TEST(ModelSelector, PruneRemovesUnsupportedAndDuplicateSurfaces) {
  const World w = wall();
  const PlanarEmOptions o;
  ModelSelector sel(w.cloud.points, w.neighbours, w.cloud.rows, o);
  const Surface good = fittedOn(w, allIndices(w.cloud.points.size()));
  Surface far = good;
  far.rect.centre += Eigen::Vector3d(0, 5, 0);
  far.rect.offset += 5;
  std::vector<Surface> s = {good, far};
  EXPECT_EQ(sel.prune(s), 1);
  ASSERT_EQ(s.size(), 1u);
  EXPECT_EQ(s[0].rect.centre, good.rect.centre);
  s = {good, good};  // a copy explains nothing more (hard scoring) and costs kappa
  EXPECT_EQ(sel.prune(s), 1);
  EXPECT_EQ(s.size(), 1u);
  s.clear();
  EXPECT_EQ(sel.prune(s), 0);
}

TEST(ModelSelector, TwoHalvesOfOneWallAreFused) {
  const World w = wall();
  std::vector<std::int32_t> left, right;
  for (std::size_t i = 0; i < w.cloud.points.size(); ++i) {
    (w.cloud.points[i].x() < 2.0 ? left : right).push_back(static_cast<std::int32_t>(i));
  }
  std::vector<Surface> s = {fittedOn(w, left), fittedOn(w, right)};
  s[0].id = 0;
  s[1].id = 1;
  std::int32_t next_id = 2;
  ModelSelector sel(w.cloud.points, w.neighbours, w.cloud.rows, PlanarEmOptions{});
  const SelectionChanges c = sel.round(s, next_id);
  EXPECT_EQ(c.fused, 1);
  ASSERT_EQ(s.size(), 1u);
  EXPECT_NEAR(s[0].rect.area(), 4.0 * 2.45, 0.2);
  EXPECT_GE(s[0].id, 2);  // a changed surface gets a new id
}

TEST(ModelSelector, ARecessedDoorIsSplitOffItsWall) {
  for (const double sigma : {0.02, 0.05}) {
    const World w = wall(0.10);
    PlanarEmOptions o;
    o.sigma_m = sigma;
    std::vector<Surface> s = {fittedOn(w, allIndices(w.cloud.points.size()))};
    std::int32_t next_id = 1;
    ModelSelector sel(w.cloud.points, w.neighbours, w.cloud.rows, o);
    const SelectionChanges c = sel.round(s, next_id);
    EXPECT_GE(c.split + c.added, 1) << "sigma " << sigma;
    EXPECT_GE(s.size(), 2u) << "sigma " << sigma;
  }
}

// A range camera's disparity staircase: the wall's points lie on two
// interleaved terraces 3 cm apart (stripes 15 cm wide). Two planes, one per
// terrace, explain them far better than one (0.28 nats per point at sigma
// 2 cm), yet they occupy the same place: they are fused into one surface.
// With the split test's offset below the terraces' step the same pair is a
// legitimate pair of surfaces and stays.
TEST(ModelSelector, TwoTerracesOfOneWallAreOneSurface) {
  World w = wall();
  std::vector<std::int32_t> lower;
  std::vector<std::int32_t> upper;
  for (std::size_t i = 0; i < w.cloud.points.size(); ++i) {
    if ((w.cloud.keys[i].row / 3) % 2 == 1) {
      w.cloud.points[i].y() += 0.03;
      upper.push_back(static_cast<std::int32_t>(i));
    } else {
      lower.push_back(static_cast<std::int32_t>(i));
    }
  }
  w.done();
  for (const double split_offset : {0.04, 0.01}) {
    PlanarEmOptions o;
    o.split_min_offset_m = split_offset;
    std::vector<Surface> s = {fittedOn(w, lower), fittedOn(w, upper)};
    s[1].id = 1;
    std::int32_t next_id = 2;
    ModelSelector sel(w.cloud.points, w.neighbours, w.cloud.rows, o);
    const SelectionChanges c = sel.round(s, next_id);
    if (split_offset == 0.04) {
      EXPECT_EQ(c.fused, 1);
      EXPECT_EQ(s.size(), 1u);
    } else {
      EXPECT_EQ(c.fused, 0);
      EXPECT_GE(s.size(), 2u);
    }
  }
}

TEST(ModelSelector, ABinIsNotASurface) {
  World w;
  std::mt19937_64 rng(2);
  testing::addCylinder(w.cloud, {0, 0, 0}, 0.25, 0.8, 0.03, 0.02, rng, 0);
  w.done();
  ModelSelector sel(w.cloud.points, w.neighbours, w.cloud.rows, PlanarEmOptions{});
  std::vector<Surface> s;
  std::int32_t next_id = 0;
  for (int r = 0; r < 3; ++r) {
    sel.round(s, next_id);
  }
  EXPECT_TRUE(s.empty());
}

TEST(ModelSelector, APlaneSeenByTooFewScansIsNotASurface) {
  World w;
  std::mt19937_64 rng(3);
  // Four scans (rows) of 200 beams: 800 points, but min_rows = 5.
  std::normal_distribution<double> noise(0.0, 0.01);
  for (int r = 0; r < 4; ++r) {
    for (int b = 0; b < 200; ++b) {
      w.cloud.points.emplace_back(0.05 * r, noise(rng), 0.02 * b);
      w.cloud.keys.push_back({0, r, b});
      w.cloud.rows.push_back(r);
    }
  }
  w.done();
  ModelSelector sel(w.cloud.points, w.neighbours, w.cloud.rows, PlanarEmOptions{});
  std::vector<Surface> s;
  std::int32_t next_id = 0;
  EXPECT_EQ(sel.round(s, next_id).added, 0);
  // The same points without rows information are a surface.
  const std::vector<std::int32_t> no_rows;
  ModelSelector any(w.cloud.points, w.neighbours, no_rows, PlanarEmOptions{});
  EXPECT_EQ(any.round(s, next_id).added, 1);
}

}  // namespace
}  // namespace pmap::em
