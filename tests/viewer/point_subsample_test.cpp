#include "pmap/viewer/point_subsample.h"

#include <gtest/gtest.h>

#include <limits>

namespace pmap::viewer {
namespace {

std::vector<Eigen::Vector3f> numbered(std::size_t count) {
  std::vector<Eigen::Vector3f> points;
  for (std::size_t i = 0; i < count; ++i) {
    points.emplace_back(float(i), 0.0f, 0.0f);
  }
  return points;
}

TEST(SubsamplePoints, EmptyInputGivesNoPoints) {
  EXPECT_TRUE(subsamplePoints({}, 10).empty());
}

TEST(SubsamplePoints, KeepsAllWhenUnderTheLimit) {
  const auto points = numbered(5);
  EXPECT_EQ(subsamplePoints(points, 5), points);
  EXPECT_EQ(subsamplePoints(points, 100), points);
}

TEST(SubsamplePoints, ZeroLimitKeepsNone) {
  EXPECT_TRUE(subsamplePoints(numbered(5), 0).empty());
}

TEST(SubsamplePoints, TakesEveryKthPointWithTheSmallestStride) {
  const auto kept = subsamplePoints(numbered(10), 3);  // stride 4: 0 4 8
  ASSERT_EQ(kept.size(), 3u);
  EXPECT_EQ(kept[0].x(), 0.0f);
  EXPECT_EQ(kept[1].x(), 4.0f);
  EXPECT_EQ(kept[2].x(), 8.0f);
}

TEST(SubsamplePoints, StaysUnderTheLimitAndIsDeterministic) {
  const auto points = numbered(1000003);
  const auto kept = subsamplePoints(points, 300000);
  EXPECT_LE(kept.size(), 300000u);
  EXPECT_GT(kept.size(), 250000u);
  EXPECT_EQ(kept, subsamplePoints(points, 300000));
}

TEST(SubsamplePoints, DropsNonFinitePoints) {
  auto points = numbered(4);
  points[1].y() = std::numeric_limits<float>::quiet_NaN();
  points[2].z() = std::numeric_limits<float>::infinity();
  const auto kept = subsamplePoints(points, 10);
  ASSERT_EQ(kept.size(), 2u);
  EXPECT_EQ(kept[1].x(), 3.0f);
}

TEST(PackFloat32, LittleEndianTriples) {
  const auto bytes = packFloat32({Eigen::Vector3f(1.0f, -2.0f, 0.0f)});
  const std::vector<std::uint8_t> expected = {0, 0, 0x80, 0x3f, 0, 0, 0, 0xc0, 0, 0, 0, 0};
  EXPECT_EQ(bytes, expected);
  EXPECT_TRUE(packFloat32({}).empty());
}

}  // namespace
}  // namespace pmap::viewer
