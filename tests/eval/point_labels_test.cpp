#include "pmap/eval/point_labels.h"

#include <gtest/gtest.h>

#include <random>

#include "pmap/common/error.h"

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

GtRectangle rect(int id, const Eigen::Vector3d& o, const Eigen::Vector3d& u,
                 const Eigen::Vector3d& v) {
  GtRectangle r;
  r.id = id;
  r.corners = {o, o + u, o + u + v, o + v};
  r.normal = u.cross(v).normalized();
  return r;
}

// The nearest object within the distance, ties to the lower id: checked
// against every object's own distance (GroundTruth::distance) at random
// points around walls, a slanted wall, a floor, a bin and a turned box.
TEST(PointLabels, Issue16_NearestObjectHitsAreTheNearestObjectWithinReach) {
  GroundTruth gt;
  gt.surfaces.push_back(rect(4, {0, 0, 0}, {6, 0, 0}, {0, 0, 2.5}));
  gt.surfaces.push_back(rect(2, {0, 2, 0}, {6, 0, 0}, {0, 0, 2.5}));
  gt.surfaces.push_back(rect(9, {0, 0, 0}, {0, 2, 0}, {6, 0, 0}));    // floor
  gt.surfaces.push_back(rect(5, {6, 0, 0}, {3, 3, 0}, {0, 0, 2.5}));  // 45 deg
  gt.cylinders.push_back({7, "bin", {3, 1}, 0.2, 0.0, 0.6});
  GtBox box;
  box.id = 1;
  box.min = {-0.3, -0.2, 0};
  box.max = {0.3, 0.2, 0.8};
  box.yaw = 0.5;
  box.centre = {4.5, 1.3};
  gt.boxes.push_back(box);
  MapPoints p;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> x(-0.5, 9.5), y(-0.5, 3.5), z(-0.2, 2.7);
  for (int i = 0; i < 20000; ++i) {
    p.xyz.emplace_back(x(rng), y(rng), z(rng));
    p.scan.push_back(i % 3);
    p.beam.push_back(i / 3);
    p.surface.push_back(-1);
  }
  NearestLabelOptions options;
  options.max_distance_m = 0.15;
  options.cell_m = 0.5;
  const auto hits = nearestObjectHits(gt, p, options);
  std::size_t labelled = 0;
  for (std::size_t i = 0; i < p.xyz.size(); ++i) {
    int expected = -1;
    double best = options.max_distance_m;
    for (const int id : {1, 2, 4, 5, 7, 9}) {  // increasing id
      const double d = gt.distance(id, p.xyz[i]);
      if (d <= best && (expected < 0 || d < best)) {
        best = d;
        expected = id;
      }
    }
    ASSERT_EQ(hits.at(p.scan[i]).at(static_cast<std::size_t>(p.beam[i])), expected) << i;
    labelled += expected >= 0 ? 1 : 0;
  }
  EXPECT_GT(labelled, 2000u);  // every kind of object was in reach of some points
}

TEST(PointLabels, Issue16_NearestObjectHitsRefuseBeamsNoMapNumbersThatWay) {
  MapPoints p;
  p.xyz = {Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones()};
  p.scan = {0, 0};
  p.beam = {0, 1};
  p.surface = {-1, -1};
  const auto hits = nearestObjectHits(GroundTruth{}, p, NearestLabelOptions{});
  EXPECT_EQ(hits.at(0), (std::vector<int>{-1, -1}));
  p.beam[1] = 1 << 30;  // would size a 4 GB label vector
  EXPECT_THROW(nearestObjectHits(GroundTruth{}, p, NearestLabelOptions{}), InputError);
  p.beam[1] = -1;
  EXPECT_THROW(nearestObjectHits(GroundTruth{}, p, NearestLabelOptions{}), InputError);
  NearestLabelOptions bad;
  bad.max_distance_m = 0;
  EXPECT_THROW(nearestObjectHits(GroundTruth{}, MapPoints{}, bad), ConfigError);
}

}  // namespace
}  // namespace pmap::eval
