// Issue 15: the scan-to-submap matcher finds a known pose without a good
// initial guess: the exact best pose of its search lattice.
#include "pmap/poses/scan_matcher.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace pmap::poses {
namespace {

// Points along the walls of a room with a few boxes in it (world frame).
std::vector<Eigen::Vector2d> room(double w, double h, bool boxes) {
  std::vector<Eigen::Vector2d> pts;
  for (double t = 0; t < w; t += 0.03) {
    pts.emplace_back(t, 0.0);
    pts.emplace_back(t, h);
  }
  for (double t = 0; t < h; t += 0.03) {
    pts.emplace_back(0.0, t);
    pts.emplace_back(w, t);
  }
  if (boxes) {
    for (double t = 0; t < 1.0; t += 0.03) {
      pts.emplace_back(2.0 + t, 1.5);
      pts.emplace_back(2.0, 1.5 + t);
      pts.emplace_back(5.0, 3.0 + t);
    }
  }
  return pts;
}

// `world` seen from `pose`: in its frame.
std::vector<Eigen::Vector2d> seenFrom(const std::vector<Eigen::Vector2d>& world, const Pose2& pose,
                                      double noise, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> n(0.0, noise);
  const Pose2 inv = inverse(pose);
  const double c = std::cos(inv.theta), s = std::sin(inv.theta);
  std::vector<Eigen::Vector2d> out;
  for (const auto& p : world) {
    out.emplace_back(c * p.x() - s * p.y() + inv.x + n(rng),
                     s * p.x() + c * p.y() + inv.y + n(rng));
  }
  return out;
}

TEST(ScanMatcher, FindsAKnownPoseFarFromTheGuess) {
  const auto world = room(8.0, 5.0, true);
  const Pose2 truth{3.2, 2.1, 0.35};
  const ScanMatcher matcher(world, ScanMatchOptions{});
  MatchWindow window;
  window.guess = {2.0, 1.4, 0.1};  // 1.4 m and 14 deg away
  window.linear_m = 2.0;
  window.angular_deg = 25.0;
  const ScanMatch m = matcher.match(seenFrom(world, truth, 0.01, 1), window, 0.5);
  ASSERT_TRUE(m.found);
  // On the lattice: within a cell (5 cm) and an angle step (at most 1 deg).
  EXPECT_NEAR(m.pose.x, truth.x, 0.05);
  EXPECT_NEAR(m.pose.y, truth.y, 0.05);
  EXPECT_NEAR(m.pose.theta, truth.theta, M_PI / 180.0);
  EXPECT_GT(m.score, 0.7);
}

// The bounds are upper bounds: branch and bound returns the same pose as
// scoring every pose of the window, also when the window reaches past the
// grid's edge (a block that starts outside the grid still overlaps it).
TEST(ScanMatcher, BranchAndBoundEqualsExhaustiveSearch) {
  const auto world = room(6.0, 4.0, true);
  const Pose2 truth{0.4, 0.3, -0.2};  // near the corner: windows leave the grid
  const auto query = seenFrom(world, truth, 0.01, 3);
  ScanMatchOptions pruned;
  ScanMatchOptions flat = pruned;
  flat.levels = 1;  // every offset scored exactly
  MatchWindow window;
  window.guess = {0.0, 0.0, 0.0};
  window.linear_m = 1.0;
  window.angular_deg = 15.0;
  const ScanMatch a = ScanMatcher(world, pruned).match(query, window, 0.1);
  const ScanMatch b = ScanMatcher(world, flat).match(query, window, 0.1);
  ASSERT_TRUE(a.found);
  ASSERT_TRUE(b.found);
  EXPECT_DOUBLE_EQ(a.score, b.score);
  EXPECT_DOUBLE_EQ(a.pose.x, b.pose.x);
  EXPECT_DOUBLE_EQ(a.pose.y, b.pose.y);
  EXPECT_DOUBLE_EQ(a.pose.theta, b.pose.theta);
}

TEST(ScanMatcher, NothingAboveTheThresholdIsNotFound) {
  const auto world = room(8.0, 5.0, true);
  const ScanMatcher matcher(world, ScanMatchOptions{});
  std::vector<Eigen::Vector2d> other;  // a different place: a lone diagonal line
  for (double t = 0; t < 3.0; t += 0.03) {
    other.emplace_back(t, 0.7 * t);
  }
  MatchWindow window;
  window.guess = {4.0, 2.5, 0.0};
  window.linear_m = 1.0;
  window.angular_deg = 10.0;
  EXPECT_FALSE(matcher.match(other, window, 0.8).found);
}

// Issue 15: the runner-up outside the best pose's neighbourhood tells an
// ambiguous place (a corridor, where straight walls match at any shift along
// it) from a unique one (a room with boxes).
TEST(ScanMatcher, Item15_TheRunnerUpTellsAnAmbiguousPlaceFromAUniqueOne) {
  std::vector<Eigen::Vector2d> corridor;  // two 30 m walls 2 m apart
  for (double t = 0; t < 30.0; t += 0.03) {
    corridor.emplace_back(t, -1.0);
    corridor.emplace_back(t, 1.0);
  }
  std::vector<Eigen::Vector2d> piece;  // 6 m of it, seen from (15, 0)
  for (const auto& p : corridor) {
    if (p.x() > 12.0 && p.x() < 18.0) {
      piece.push_back(p);
    }
  }
  const Pose2 truth{15.0, 0.0, 0.0};
  MatchWindow window;
  window.guess = {14.0, 0.2, 0.0};
  window.linear_m = 3.0;
  window.angular_deg = 10.0;
  MatchWindow near;
  near.linear_m = 1.0;
  near.angular_deg = 5.0;

  const ScanMatcher in_corridor(corridor, ScanMatchOptions{});
  const auto query = seenFrom(piece, truth, 0.01, 2);
  const ScanMatch best = in_corridor.match(query, window, 0.3);
  ASSERT_TRUE(best.found);
  near.guess = best.pose;
  const ScanMatch runner_up = in_corridor.matchOutside(query, window, near, 0.9 * best.score);
  ASSERT_TRUE(runner_up.found) << "a corridor looks the same 1 m further";
  EXPECT_GE(
      std::max(std::abs(runner_up.pose.x - best.pose.x), std::abs(runner_up.pose.y - best.pose.y)),
      1.0 - 1e-9);
  EXPECT_GE(runner_up.score, 0.9 * best.score);
  EXPECT_TRUE(in_corridor.anyOutside(query, window, near, 0.9 * best.score));

  const auto world = room(8.0, 5.0, true);
  const Pose2 in_room{3.2, 2.1, 0.35};
  const ScanMatcher room_matcher(world, ScanMatchOptions{});
  MatchWindow around_room;
  around_room.guess = {3.0, 2.0, 0.3};
  around_room.linear_m = 2.0;
  around_room.angular_deg = 20.0;
  const auto room_query = seenFrom(world, in_room, 0.01, 3);
  const ScanMatch room_best = room_matcher.match(room_query, around_room, 0.3);
  ASSERT_TRUE(room_best.found);
  EXPECT_NEAR(room_best.pose.x, in_room.x, 0.05);
  near.guess = room_best.pose;
  EXPECT_FALSE(
      room_matcher.matchOutside(room_query, around_room, near, 0.9 * room_best.score).found)
      << "the room with boxes is unique in its window";
  EXPECT_FALSE(room_matcher.anyOutside(room_query, around_room, near, 0.9 * room_best.score));
}

// anyOutside() looks at the excluded poses' angles first and stops at the
// first pose above the threshold: whatever the order, it says
// yes exactly when matchOutside() finds a pose, i.e. when the best pose
// outside the excluded ones scores strictly more than the threshold.
TEST(ScanMatcher, Item15_AnyOutsideAgreesWithTheFullSearch) {
  const auto world = room(8.0, 5.0, true);
  const ScanMatcher matcher(world, ScanMatchOptions{});
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 12; ++trial) {
    const Pose2 truth{4.0 + 1.5 * u(rng), 2.5 + u(rng), 0.5 * u(rng)};
    const auto query = seenFrom(world, truth, 0.01, static_cast<unsigned>(trial));
    MatchWindow window;
    window.guess = {truth.x + 0.5 * u(rng), truth.y + 0.5 * u(rng), truth.theta + 0.1 * u(rng)};
    window.linear_m = 1.2;
    window.angular_deg = 12.0;
    MatchWindow excluded;  // around the truth, or anywhere in the window
    excluded.guess = trial % 2 == 0 ? truth
                                    : Pose2{window.guess.x + u(rng), window.guess.y + u(rng),
                                            window.guess.theta + 0.2 * u(rng)};
    excluded.linear_m = 0.3 + 0.3 * (1.0 + u(rng));
    excluded.angular_deg = 5.0;
    const ScanMatch outside = matcher.matchOutside(query, window, excluded, 0.0);
    ASSERT_TRUE(outside.found) << "trial " << trial;
    EXPECT_TRUE(matcher.anyOutside(query, window, excluded, outside.score - 1e-9))
        << "trial " << trial;
    EXPECT_FALSE(matcher.anyOutside(query, window, excluded, outside.score)) << "trial " << trial;
  }
}

// A corridor is ambiguous along its axis only: with the line through the
// best pose along the axis left out, nothing else scores nearly as well;
// with a line across it, or with a twin corridor beside it, something does.
TEST(ScanMatcher, Item15_AnAmbiguityAlongOneLineIsToldFromOthers) {
  std::vector<Eigen::Vector2d> corridor;  // two 30 m walls 2 m apart
  for (double t = 0; t < 30.0; t += 0.03) {
    corridor.emplace_back(t, -1.0);
    corridor.emplace_back(t, 1.0);
  }
  std::vector<Eigen::Vector2d> piece;  // 6 m of it, seen from (15, 0)
  for (const auto& p : corridor) {
    if (p.x() > 12.0 && p.x() < 18.0) {
      piece.push_back(p);
    }
  }
  const Pose2 truth{15.0, 0.0, 0.0};
  MatchWindow window;
  window.guess = {14.0, 0.2, 0.0};
  window.linear_m = 3.0;
  window.angular_deg = 10.0;
  const ScanMatcher matcher(corridor, ScanMatchOptions{});
  const auto query = seenFrom(piece, truth, 0.01, 2);
  const ScanMatch best = matcher.match(query, window, 0.3);
  ASSERT_TRUE(best.found);
  MatchWindow near;
  near.guess = best.pose;
  near.linear_m = 1.0;
  near.angular_deg = 5.0;
  const double runner_up = 0.9 * best.score;
  ASSERT_TRUE(matcher.anyOutside(query, window, near, runner_up));
  EXPECT_FALSE(matcher.anyOutsideBand(query, window, near, {1.0, 0.0}, 0.1, runner_up));
  EXPECT_FALSE(matcher.anyOutsideBand(query, window, near, {-1.0, 0.0}, 0.1, runner_up));
  EXPECT_TRUE(matcher.anyOutsideBand(query, window, near, {0.0, 1.0}, 0.1, runner_up));

  // A twin 2.5 m to the side: its axis is no way out.
  std::vector<Eigen::Vector2d> twins = corridor;
  for (const auto& p : corridor) {
    twins.emplace_back(p.x(), p.y() + 2.5);
  }
  const ScanMatcher twin_matcher(twins, ScanMatchOptions{});
  const ScanMatch twin_best = twin_matcher.match(query, window, 0.3);
  ASSERT_TRUE(twin_best.found);
  near.guess = twin_best.pose;
  EXPECT_TRUE(
      twin_matcher.anyOutsideBand(query, window, near, {1.0, 0.0}, 0.1, 0.9 * twin_best.score));
}

}  // namespace
}  // namespace pmap::poses
