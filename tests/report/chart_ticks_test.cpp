#include "pmap/report/chart_ticks.h"

#include <gtest/gtest.h>

#include <cmath>

namespace pmap::report {
namespace {

TEST(ChartTicks, NiceRangeCoversTheDataWithWholeSteps) {
  const AxisRange r = niceRange(0.13, 9.7, 5);
  EXPECT_DOUBLE_EQ(r.lo, 0.0);
  EXPECT_DOUBLE_EQ(r.hi, 10.0);
  const std::vector<double> ticks = linearTicks(r, 5);
  ASSERT_EQ(ticks.size(), 6u);
  EXPECT_DOUBLE_EQ(ticks[1], 2.0);
}

TEST(ChartTicks, SingleValueAndNonFiniteRanges) {
  const AxisRange r = niceRange(4.0, 4.0);
  EXPECT_LT(r.lo, 4.0);
  EXPECT_GT(r.hi, 4.0);
  const AxisRange zero = niceRange(0.0, 0.0);
  EXPECT_LT(zero.lo, 0.0);
  EXPECT_GT(zero.hi, 0.0);
  const AxisRange bad = niceRange(NAN, 1.0);
  EXPECT_DOUBLE_EQ(bad.lo, 0.0);
  EXPECT_DOUBLE_EQ(bad.hi, 1.0);
}

TEST(ChartTicks, TinyVariationsGetDistinctLabels) {
  const AxisRange r = niceRange(0.9929001, 0.9929013);
  const std::vector<double> ticks = linearTicks(r, 5);
  ASSERT_GE(ticks.size(), 3u);
  for (std::size_t i = 1; i < ticks.size(); ++i) {
    EXPECT_NE(tickLabel(ticks[i]), tickLabel(ticks[i - 1]));
  }
}

TEST(ChartTicks, PaddedRange) {
  const AxisRange r = paddedRange(0.0, 100.0);
  EXPECT_DOUBLE_EQ(r.lo, -2.0);
  EXPECT_DOUBLE_EQ(r.hi, 102.0);
  const AxisRange single = paddedRange(3.0, 3.0);
  EXPECT_LT(single.lo, 3.0);
  EXPECT_GT(single.hi, 3.0);
}

TEST(ChartTicks, LogRangeAndTicks) {
  const AxisRange r = logRange(0.3, 450.0);
  EXPECT_DOUBLE_EQ(r.lo, -1.0);
  EXPECT_DOUBLE_EQ(r.hi, 3.0);
  const std::vector<double> ticks = logTicks(r);
  ASSERT_EQ(ticks.size(), 5u);  // four decades: powers of ten only
  EXPECT_DOUBLE_EQ(ticks.front(), 0.1);
  EXPECT_DOUBLE_EQ(ticks.back(), 1000.0);
  const std::vector<double> fine = logTicks(logRange(2.0, 30.0));
  EXPECT_EQ(fine.size(), 7u);  // 1 2 5 10 20 50 100
}

TEST(ChartTicks, Labels) {
  EXPECT_EQ(tickLabel(0.0), "0");
  EXPECT_EQ(tickLabel(0.25), "0.25");
  EXPECT_EQ(tickLabel(1500.0), "1500");
  EXPECT_EQ(tickLabel(1e-3), "0.001");
}

}  // namespace
}  // namespace pmap::report
