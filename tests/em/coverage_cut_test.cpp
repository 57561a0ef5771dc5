#include "pmap/em/coverage_cut.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <random>

#include "em_test_worlds.h"
#include "pmap/em/surface_fit.h"

namespace pmap::em {
namespace {

using testing::allIndices;

// The axis-aligned rectangle [x0, x1] x [y0, y1] of the plane z = 0.
Rectangle box(double x0, double x1, double y0, double y1) {
  Rectangle r;
  r.centre = {0.5 * (x0 + x1), 0.5 * (y0 + y1), 0.0};
  r.half_u = 0.5 * (x1 - x0);
  r.half_v = 0.5 * (y1 - y0);
  return r;
}

// An L: the long arm [0, 8] x [0, 2] and the short arm [0, 2] x (2, 5].
testing::Cloud lShape(double step) {
  testing::Cloud c;
  std::mt19937_64 rng(1);
  testing::addPlane(c, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 8.0, 5.0, step, 0.0, rng, 0,
                    [](double x, double y) { return y <= 2.0 + 1e-9 || x <= 2.0 + 1e-9; });
  return c;
}

TEST(CoverageCut, AnLIsCutInTwoWhereTheLargerPartIsLargest) {
  const testing::Cloud c = lShape(0.1);
  const auto members = allIndices(c.points.size());
  const std::vector<double> loss(members.size(), 5.0);
  const auto cut =
      coverageCut(c.points, members, loss, box(0, 8, 0, 5), 0.15, 20.0, 200.0, 60, true);
  ASSERT_TRUE(cut.has_value());
  EXPECT_EQ(cut->keep, CutKeep::kBoth);
  // Both ways of cutting the L leave two full rectangles; the chosen one
  // keeps the corner with the long arm (81 x 21 points).
  const auto& a = cut->parts.part_a;
  const auto& b = cut->parts.part_b;
  EXPECT_EQ(a.size() + b.size(), members.size());
  EXPECT_EQ(std::max(a.size(), b.size()), 81u * 21u);
  const auto& longer = a.size() > b.size() ? a : b;
  for (const std::int32_t i : longer) {
    EXPECT_LE(c.points[i].y(), 2.0 + 1e-9);
  }
  // Empty area saved: 40 m^2 bounding box - 22 m^2 covered, minus kappa.
  EXPECT_NEAR(cut->estimated_gain, 20.0 * 18.0 - 200.0, 20.0);
}

// A ceiling continued around a corner: a 30 m x 2.2 m leg, whose outer
// corner the turning robot's scans did not reach (a 3 m triangle), and the
// first 0.7 m of the next leg at its end. Eq. (29)'s rectangle around the L
// is turned by the appendage, so no cut along its own axes separates the
// legs; the cut is searched in the refitted parts' frame.
TEST(CoverageCut, AnLWhoseRectangleTheAppendageTurnedIsCutIntoItsLegs) {
  testing::Cloud c;
  std::mt19937_64 rng(3);
  testing::addPlane(
      c, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 30.0, 2.9, 0.1, 0.0, rng, 0,
      [](double x, double y) { return (y <= 2.2 + 1e-9 || x >= 27.8 - 1e-9) && y >= x - 27.0; });
  const auto members = allIndices(c.points.size());
  Rectangle turned = box(0, 30, 0, 2.9);
  ASSERT_EQ(fitRectangle(c.points, members, turned), FitStatus::kOk);
  ASSERT_GT(std::abs(turned.axis_u.y()), std::sin(1.0 * M_PI / 180.0));  // the premise
  const std::vector<double> loss(members.size(), 5.0);
  const auto cut = coverageCut(c.points, members, loss, turned, 0.15, 20.0, 200.0, 60, true);
  ASSERT_TRUE(cut.has_value());
  EXPECT_EQ(cut->keep, CutKeep::kBoth);
  const auto& a = cut->parts.part_a;
  const auto& b = cut->parts.part_b;
  const auto& leg = a.size() > b.size() ? a : b;
  const auto& appendage = a.size() > b.size() ? b : a;
  // The cut runs along a true axis: across the leg where the corner begins,
  // or along the leg's side.
  auto extent = [&](const std::vector<std::int32_t>& part, int axis) {
    double lo = INFINITY, hi = -INFINITY;
    for (const std::int32_t i : part) {
      lo = std::min(lo, c.points[static_cast<std::size_t>(i)][axis]);
      hi = std::max(hi, c.points[static_cast<std::size_t>(i)][axis]);
    }
    return std::make_pair(lo, hi);
  };
  const bool across = extent(leg, 0).second < extent(appendage, 0).first;
  const bool along = extent(leg, 1).second < extent(appendage, 1).first;
  EXPECT_TRUE(across || along);
  EXPECT_GE(extent(appendage, 0).first, 27.0);
  // Refitted alone, each part is a full rectangle along the true axes.
  for (const auto* part : {&leg, &appendage}) {
    Rectangle r = turned;
    ASSERT_EQ(fitRectangle(c.points, *part, r), FitStatus::kOk);
    EXPECT_LT(std::min(std::abs(r.axis_u.x()), std::abs(r.axis_u.y())), 1e-6);
  }
}

// Two ceiling pieces in the plane z = 0: the first leg, and the second one
// with the corner square (the non-canonical cut of an L), or something else.
struct TwoPieces {
  testing::Cloud c;
  std::vector<std::int32_t> big, other;
  Rectangle big_rect, other_rect;
  TwoPieces(double x0, double x1, double y0, double y1, double z = 0.0) {
    std::mt19937_64 rng(4);
    testing::addPlane(c, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 20.0, 2.2, 0.1, 0.0, rng, 0);
    big = allIndices(c.points.size());
    testing::addPlane(c, {x0, y0, z}, {1, 0, 0}, {0, 1, 0}, x1 - x0, y1 - y0, 0.1, 0.0, rng, 1);
    for (std::size_t i = big.size(); i < c.points.size(); ++i) {
      other.push_back(static_cast<std::int32_t>(i));
    }
    big_rect = box(0, 20, 0, 2.2);
    other_rect = box(x0, x1, y0, y1);
    other_rect.centre.z() = z;
  }
};

TEST(CornerTransfer, TheFirstLegTakesTheCornerSquareOfAnL) {
  const TwoPieces l(20.05, 22.25, 0.0, 12.0);
  const auto moving = cornerTransfer(l.c.points, l.big_rect, l.big, l.other_rect, l.other, 0.02);
  ASSERT_FALSE(moving.empty());
  for (const std::int32_t i : l.other) {
    const bool in_square = l.c.points[static_cast<std::size_t>(i)].y() <= 2.2 + 0.02;
    EXPECT_EQ(std::binary_search(moving.begin(), moving.end(), i), in_square) << i;
  }
}

TEST(CornerTransfer, CollinearPiecesARoomBesideOrADoorBehindAreNoL) {
  const TwoPieces collinear(20.05, 30.0, 0.0, 2.2);  // the corridor continued
  EXPECT_TRUE(cornerTransfer(collinear.c.points, collinear.big_rect, collinear.big,
                             collinear.other_rect, collinear.other, 0.02)
                  .empty());
  const TwoPieces room(8.0, 13.0, 0.0, 6.0);  // beside the corridor, not beyond its end
  EXPECT_TRUE(
      cornerTransfer(room.c.points, room.big_rect, room.big, room.other_rect, room.other, 0.02)
          .empty());
  const TwoPieces recessed(20.05, 22.25, 0.0, 12.0, 0.1);  // 10 cm off the plane
  EXPECT_TRUE(cornerTransfer(recessed.c.points, recessed.big_rect, recessed.big,
                             recessed.other_rect, recessed.other, 0.02)
                  .empty());
}

TEST(CoverageCut, ADenseRectangleWithASparseStripIsTrimmed) {
  testing::Cloud c;
  std::mt19937_64 rng(2);
  testing::addPlane(c, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 2.0, 2.0, 0.05, 0.0, rng, 0);
  const std::size_t dense = c.points.size();
  for (int k = 0; k < 10; ++k) {
    c.points.emplace_back(2.3 + 0.3 * k, 1.0, 0.0);  // a thin strip out to x = 5
  }
  const auto members = allIndices(c.points.size());
  const std::vector<double> no_loss(members.size(), 0.0);
  const Rectangle r = box(0, 5, 0, 2);
  const auto cut = coverageCut(c.points, members, no_loss, r, 0.15, 20.0, 200.0, 60, true);
  ASSERT_TRUE(cut.has_value());
  EXPECT_EQ(cut->keep, CutKeep::kPartA);
  EXPECT_EQ(cut->parts.part_a, allIndices(dense));
  EXPECT_EQ(cut->parts.part_b.size(), 10u);
  EXPECT_GT(cut->estimated_gain, 0.0);
  // Without trims nothing gains (the strip is too small to be a part).
  EXPECT_FALSE(coverageCut(c.points, members, no_loss, r, 0.15, 20.0, 200.0, 60, false));
  // When the strip's points would be badly lost, no trim either.
  const std::vector<double> big_loss(members.size(), 100.0);
  const auto kept = coverageCut(c.points, members, big_loss, r, 0.15, 20.0, 200.0, 60, true);
  EXPECT_TRUE(!kept || kept->keep != CutKeep::kPartA);
}

TEST(CoverageCut, WithoutTrimsOnlyCutsKeepingBothParts) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int cuts = 0;
  for (int t = 0; t < 60; ++t) {
    // Random unions of two or three axis-aligned blocks of random density.
    testing::Cloud c;
    const int blocks = 2 + t % 2;
    for (int b = 0; b < blocks; ++b) {
      const double x0 = 4 * u(rng), y0 = 4 * u(rng);
      testing::addPlane(c, {x0, y0, 0}, {1, 0, 0}, {0, 1, 0}, 0.2 + 3 * u(rng), 0.2 + 3 * u(rng),
                        0.05 + 0.3 * u(rng), 0.0, rng, b);
    }
    const auto members = allIndices(c.points.size());
    std::vector<double> loss(members.size());
    for (double& l : loss) {
      l = t % 3 == 0 ? 0.0 : 2.0 * u(rng);
    }
    Rectangle r;
    ASSERT_EQ(fitSurface(c.points, members, r), FitStatus::kOk);
    const auto cut = coverageCut(c.points, members, loss, r, 0.15, 20.0, 50.0, 20, false);
    if (cut) {
      ++cuts;
      EXPECT_EQ(cut->keep, CutKeep::kBoth);
      EXPECT_GE(cut->parts.part_a.size(), 20u);
      EXPECT_GE(cut->parts.part_b.size(), 20u);
      EXPECT_EQ(cut->parts.part_a.size() + cut->parts.part_b.size(), members.size());
      EXPECT_GT(cut->estimated_gain, 0.0);
    }
  }
  EXPECT_GT(cuts, 5);
}

TEST(CoverageCut, AFullRectangleOrTooFewMembersGiveNoCut) {
  testing::Cloud c;
  std::mt19937_64 rng(4);
  testing::addPlane(c, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 3.0, 2.0, 0.05, 0.0, rng, 0);
  const auto members = allIndices(c.points.size());
  const std::vector<double> loss(members.size(), 0.0);
  EXPECT_FALSE(coverageCut(c.points, members, loss, box(0, 3, 0, 2), 0.15, 20, 200, 60, true));
  EXPECT_FALSE(coverageCut(c.points, {}, {}, box(0, 3, 0, 2), 0.15, 20, 200, 60, true));
  EXPECT_FALSE(coverageCut(c.points, {0, 1, 2}, {0, 0, 0}, box(0, 3, 0, 2), 0.15, 20, 0, 60, true));
}

// An L whose rectangle three stray members on its plane stretch over 1e7 to
// 1e12 m (a mis-placed scan): the cut trims the strays off, and the grid
// behind it holds the occupied cells only (before: cols x rows cells, up to
// 1e13 of them, or an int overflow).
TEST(CoverageCut, Item12_StraysFarAwayAreTrimmedInTheMembersMemory) {
  for (const double far_m : {1e7, 1e9, 1e12}) {
    SCOPED_TRACE(far_m);
    testing::Cloud c = lShape(0.1);
    const std::size_t l_points = c.points.size();
    c.points.push_back({far_m, 1.0, 0.0});
    c.points.push_back({far_m, 1.5, 0.0});
    c.points.push_back({far_m - 1.0, 1.0, 0.0});
    const auto members = allIndices(c.points.size());
    const std::vector<double> loss(members.size(), 5.0);
    const auto cut =
        coverageCut(c.points, members, loss, box(0, far_m, 0, 5), 0.15, 20.0, 200.0, 60, true);
    ASSERT_TRUE(cut.has_value());
    EXPECT_EQ(cut->keep, CutKeep::kPartA);
    EXPECT_EQ(cut->parts.part_a.size(), l_points);
    EXPECT_EQ(cut->parts.part_b.size(), 3u);
  }
}

}  // namespace
}  // namespace pmap::em
