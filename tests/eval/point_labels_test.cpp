#include "pmap/eval/point_labels.h"

#include <gtest/gtest.h>

namespace pmap::eval {
namespace {

TEST(PointLabels, LabelsComeFromTheBeamsTrueRay) {
  GroundTruth gt;
  gt.hits[0] = {7, 7, -1};
  gt.hits[2] = {3};
  MapPoints p;
  p.xyz.assign(6, Eigen::Vector3d::Zero());
  p.scan = {0, 0, 2, 1, 0, 2};
  p.beam = {1, 2, 0, 0, 5, -1};
  p.surface.assign(6, -1);
  const std::vector<int> labels = pointLabels(gt, p);
  EXPECT_EQ(labels, (std::vector<int>{7, -1, 3, kNoLabelEntry, kNoLabelEntry, kNoLabelEntry}));
}

TEST(PointLabels, EmptyInputs) {
  EXPECT_TRUE(pointLabels(GroundTruth{}, MapPoints{}).empty());
  EXPECT_TRUE(countHits(GroundTruth{}).empty());
}

TEST(PointLabels, HitsCountEveryBeamOfEveryScanButNothing) {
  GroundTruth gt;
  gt.hits[0] = {7, 7, -1, 3};
  gt.hits[5] = {7, -1, -1};
  const auto hits = countHits(gt);
  EXPECT_EQ(hits.size(), 2u);
  EXPECT_EQ(hits.at(7), 3u);
  EXPECT_EQ(hits.at(3), 1u);
  EXPECT_EQ(hits.count(-1), 0u);
}

}  // namespace
}  // namespace pmap::eval
