#include "pmap/refine/boundary_refiner.h"

#include <gtest/gtest.h>

#include <cmath>

#include "pmap/refine/seams.h"
#include "refine_world.h"

namespace pmap::refine {
namespace {

using testing::rectangle;
const Eigen::Vector3d kX = Eigen::Vector3d::UnitX();

double angleDeg(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::acos(std::min(1.0, std::abs(a.dot(b)))) * 180.0 / M_PI;
}

// Largest in-plane distance of a's corners on the edge nearest b's plane to
// the line where a and b meet.
double seamGap(const em::Rectangle& a, const em::Rectangle& b) {
  double best = INFINITY;
  const auto c = a.corners();
  for (std::size_t e = 0; e < 4; ++e) {
    const double d0 = distanceToIntersection(a.normal, b.normal, b.offset, c[e]);
    const double d1 = distanceToIntersection(a.normal, b.normal, b.offset, c[(e + 1) % 4]);
    best = std::min(best, std::max(d0, d1));
  }
  return best;
}

TEST(RefineBoundaries, AWallAndItsCeilingEndOnTheirIntersection) {
  for (const double sigma : {0.02, 0.05}) {
    testing::Scene scene = testing::wallUnderCeiling(sigma);
    // EM-like rectangles: the wall stops 8 cm under the ceiling, the ceiling
    // 6 cm short of the wall (where the laser's points end).
    const auto before = scene.surfaces;
    const BoundaryResult r =
        refineBoundaries(scene.points, scene.samples, sigma, RefineOptions{}, scene.surfaces);
    EXPECT_EQ(r.termination, "CONVERGENCE");
    EXPECT_EQ(r.seams.size(), 2u);
    EXPECT_LT(r.final_cost, r.initial_cost);
    EXPECT_TRUE(r.reverted_ids.empty());
    const em::Rectangle& wall = scene.surfaces[0].rect;
    const em::Rectangle& ceiling = scene.surfaces[1].rect;
    EXPECT_LT(seamGap(wall, ceiling), 0.005) << sigma;
    EXPECT_LT(seamGap(ceiling, wall), 0.005) << sigma;
    // The seam lies where the true surfaces meet (z = 2.7, y = 0).
    EXPECT_NEAR(wall.centre.z() + wall.half_v, 2.7, 0.01);
    // Faithful to the measurements: the planes barely turn, the far edges stay.
    EXPECT_LT(angleDeg(wall.normal, before[0].rect.normal), 0.1);
    EXPECT_LT(angleDeg(ceiling.normal, before[1].rect.normal), 0.1);
    EXPECT_NEAR(wall.centre.z() - wall.half_v, 0.0, 0.01);
    EXPECT_NEAR(wall.half_u, 2.0, 0.01);
  }
}

TEST(RefineBoundaries, ALoneSurfaceIsLeftAsItIs) {
  testing::Scene scene = testing::wallUnderCeiling(0.02);
  scene.surfaces.resize(1);
  scene.samples.resize(1);
  const em::Rectangle before = scene.surfaces[0].rect;
  const BoundaryResult r =
      refineBoundaries(scene.points, scene.samples, 0.02, RefineOptions{}, scene.surfaces);
  EXPECT_EQ(r.termination, "nothing to refine");
  EXPECT_EQ(scene.surfaces[0].rect.centre, before.centre);
  EXPECT_EQ(scene.surfaces[0].rect.normal, before.normal);
}

TEST(RefineBoundaries, ParallelNeighboursKeepTheirOwnPlanes) {
  // A door recessed 10 cm beside its wall, and a ceiling over the wall only:
  // the wall meets the ceiling, the door meets nothing and must not move.
  std::mt19937 rng(11);
  testing::Scene scene;
  const em::Rectangle wall = rectangle(Eigen::Vector3d::UnitY(), {2, 0, 1.3}, kX, 2.0, 1.3);
  const em::Rectangle door = rectangle(Eigen::Vector3d::UnitY(), {4.5, 0.1, 1.0}, kX, 0.45, 1.0);
  const em::Rectangle ceiling = rectangle(-Eigen::Vector3d::UnitZ(), {2, 1, 2.7}, kX, 2.0, 1.0);
  testing::appendSurface(wall, wall, 0.02, rng, scene);
  testing::appendSurface(door, door, 0.02, rng, scene);
  testing::appendSurface(ceiling, ceiling, 0.02, rng, scene);
  const auto before = scene.surfaces;
  const BoundaryResult r =
      refineBoundaries(scene.points, scene.samples, 0.02, RefineOptions{}, scene.surfaces);
  for (const Seam& s : r.seams) {
    EXPECT_NE(s.surface, 1u);
    EXPECT_NE(s.other, 1u);
  }
  EXPECT_EQ(scene.surfaces[1].rect.centre, before[1].rect.centre);
  EXPECT_EQ(scene.surfaces[1].rect.normal, before[1].rect.normal);
  EXPECT_NEAR(scene.surfaces[0].rect.normal.dot(scene.surfaces[1].rect.normal), 1.0, 1e-6);
  EXPECT_LT(seamGap(scene.surfaces[0].rect, scene.surfaces[2].rect), 0.005);
}

TEST(RefineBoundaries, ManhattanPriorSnapsOnlyWithinItsTolerance) {
  for (const double tilt_deg : {0.5, 5.0}) {
    std::mt19937 rng(13);
    testing::Scene scene;
    const double t = tilt_deg * M_PI / 180.0;
    const em::Rectangle a = rectangle(Eigen::Vector3d::UnitY(), {2, 0, 1.3}, kX, 2.0, 1.3);
    const em::Rectangle b = rectangle(Eigen::Vector3d(std::cos(t), std::sin(t), 0), {8, 5, 1.3},
                                      Eigen::Vector3d::UnitZ(), 1.3, 2.0);
    testing::appendSurface(a, a, 0.0, rng, scene);
    testing::appendSurface(b, b, 0.0, rng, scene);
    RefineOptions o;
    o.manhattan = true;
    const BoundaryResult r = refineBoundaries(scene.points, scene.samples, 0.02, o, scene.surfaces);
    const double angle = angleDeg(scene.surfaces[0].rect.normal, scene.surfaces[1].rect.normal);
    if (tilt_deg < o.manhattan_tolerance_deg) {
      EXPECT_EQ(r.manhattan_pairs, 1u);
      EXPECT_NEAR(angle, 90.0, 0.01);
    } else {
      EXPECT_EQ(r.manhattan_pairs, 0u);
      EXPECT_NEAR(angle, 90.0 - tilt_deg, 1e-9);
    }
  }
}

TEST(RefineBoundaries, ConflictingSeamsGiveUpRatherThanTurnPlanes) {
  // One straight wall edge under two ceiling pieces 6 cm apart in height: it
  // cannot end on both; the planes must not tilt to pretend it does.
  std::mt19937 rng(19);
  testing::Scene scene;
  const em::Rectangle wall = rectangle(Eigen::Vector3d::UnitY(), {4, 0, 1.3}, kX, 4.0, 1.3);
  const em::Rectangle low = rectangle(-Eigen::Vector3d::UnitZ(), {2, 1, 2.70}, kX, 2.0, 0.95);
  const em::Rectangle high = rectangle(-Eigen::Vector3d::UnitZ(), {6, 1, 2.76}, kX, 2.0, 0.95);
  for (const em::Rectangle& r : {wall, low, high}) {
    testing::appendSurface(r, r, 0.02, rng, scene);
  }
  const auto before = scene.surfaces;
  const BoundaryResult r =
      refineBoundaries(scene.points, scene.samples, 0.02, RefineOptions{}, scene.surfaces);
  EXPECT_EQ(r.termination, "CONVERGENCE");
  for (std::size_t j = 0; j < 3; ++j) {
    EXPECT_LT(angleDeg(scene.surfaces[j].rect.normal, before[j].rect.normal), 0.1) << j;
  }
}

TEST(RefineBoundaries, SameInputGivesTheSameSurfaces) {
  testing::Scene a = testing::wallUnderCeiling(0.02);
  testing::Scene b = testing::wallUnderCeiling(0.02);
  refineBoundaries(a.points, a.samples, 0.02, RefineOptions{}, a.surfaces);
  refineBoundaries(b.points, b.samples, 0.02, RefineOptions{}, b.surfaces);
  for (std::size_t j = 0; j < a.surfaces.size(); ++j) {
    EXPECT_EQ(a.surfaces[j].rect.centre, b.surfaces[j].rect.centre);
    EXPECT_EQ(a.surfaces[j].rect.normal, b.surfaces[j].rect.normal);
  }
}

}  // namespace
}  // namespace pmap::refine
