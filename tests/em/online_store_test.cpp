#include "pmap/em/online_store.h"

#include <gtest/gtest.h>

namespace pmap::em {
namespace {

/// One scan of `n` points on a vertical line at x = row (group 0).
void appendRow(OnlineStore& store, int row, int n) {
  std::vector<Eigen::Vector3d> points;
  std::vector<GridKey> keys;
  for (int c = 0; c < n; ++c) {
    points.emplace_back(row, 0.0, 0.01 * c);
    keys.push_back({0, row, c});
  }
  store.appendScan(points, keys);
}

TEST(OnlineStore, MeasurementsStayInPlaceWhileTheReserveLasts) {
  // Growing a vector copies it all in one scan (the run's slowest scans):
  // within the reserve nothing moves, beyond it the store still grows.
  OnlineStore store(3, 50000);
  appendRow(store, 0, 500);
  const Eigen::Vector3d* first = &store.point(0);
  for (int row = 1; row < 100; ++row) {
    appendRow(store, row, 500);
  }
  EXPECT_EQ(store.size(), 50000u);
  EXPECT_EQ(&store.point(0), first);
  appendRow(store, 100, 500);
  EXPECT_EQ(store.size(), 50500u);
  EXPECT_EQ(store.point(50499), Eigen::Vector3d(100, 0, 4.99));
  EXPECT_EQ(store.best(50499), -1);
}

TEST(OnlineStore, ScansAreLinkedToTheirNeighboursWhateverTheReserve) {
  for (const std::size_t reserved : {std::size_t{0}, std::size_t{4}, kReservedMeasurements}) {
    OnlineStore store(2, reserved);
    appendRow(store, 0, 3);
    appendRow(store, 1, 3);
    ASSERT_EQ(store.size(), 6u);
    // The middle point of the second scan has neighbours in its scan and in
    // the scan before.
    int linked = 0;
    for (const std::int32_t n : store.neighbours()[4]) {
      linked += n >= 0 ? 1 : 0;
    }
    EXPECT_EQ(linked, 3) << "reserve " << reserved;
    EXPECT_EQ(store.window().size(), 2u);
  }
}

}  // namespace
}  // namespace pmap::em
