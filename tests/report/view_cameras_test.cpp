#include "pmap/report/view_cameras.h"

#include <gtest/gtest.h>

#include <cmath>

#include "report_test_model.h"

namespace pmap::report {
namespace {

TEST(ViewCameras, LongestStraightStretchOfAnLPath) {
  std::vector<Eigen::Vector3d> path;
  for (int i = 0; i <= 20; ++i) {
    path.emplace_back(0.25 * i, 0, 0);  // 5 m along x
  }
  for (int i = 1; i <= 40; ++i) {
    path.emplace_back(5, 0.25 * i, 0);  // then 10 m along y
  }
  const PathStretch s = longestStraightStretch(path);
  EXPECT_NEAR(s.length_m, 10.0, 0.3);
  EXPECT_NEAR(s.start.x(), 5.0, 0.3);
  EXPECT_NEAR(s.end.y(), 10.0, 1e-9);
  EXPECT_EQ(longestStraightStretch({}).length_m, 0.0);
  EXPECT_EQ(longestStraightStretch({Eigen::Vector3d::Zero()}).length_m, 0.0);
}

TEST(ViewCameras, PerspectiveLooksAlongThePathAtEyeHeight) {
  const auto model = test::corridor();
  MapViewOptions o;
  const PerspectiveView v = perspectiveView(model, mapBox(model), o);
  ASSERT_TRUE(v.on_path);
  const Eigen::Vector3d eye = v.camera.eye();
  EXPECT_NEAR(eye.x(), 0.5, 1e-6);
  EXPECT_NEAR(eye.z(), o.eye_height_m, 1e-6);
  const Eigen::Vector3d forward = (v.camera.target - eye).normalized();
  EXPECT_GT(forward.x(), 0.95);
  EXPECT_LT(forward.z(), 0.0);  // tilted down
  EXPECT_FALSE(v.camera.orthographic);
}

TEST(ViewCameras, ThreeQuarterViewWithoutAPath) {
  auto model = test::corridor();
  model.path.clear();
  const auto box = mapBox(model);
  const PerspectiveView v = perspectiveView(model, box, MapViewOptions{});
  EXPECT_FALSE(v.on_path);
  EXPECT_TRUE(box.contains(v.camera.target));
  EXPECT_FALSE(box.contains(v.camera.eye()));
  EXPECT_GT(v.camera.eye().z(), box.max().z());
}

TEST(ViewCameras, TopViewFramesTheMap) {
  const auto model = test::corridor();
  MapViewOptions o;
  const auto box = mapBox(model);
  const OrbitCamera c = topCamera(box, o);
  EXPECT_TRUE(c.orthographic);
  EXPECT_DOUBLE_EQ(c.elevation_deg, 90.0);
  const double m_per_px = topMetresPerPixel(c, o);
  // 10.5 m (with margin) across 1280 px: the width decides.
  EXPECT_NEAR(m_per_px * o.width_px, 1.05 * 10.0, 1e-6);
  EXPECT_GE(m_per_px * o.height_px, 2.0);
  const OrbitCamera empty = topCamera(Eigen::AlignedBox3d(), o);
  EXPECT_GT(empty.distance_m, 0.0);
}

TEST(ViewCameras, FloorHeightAndOptions) {
  auto model = test::corridor();
  for (auto& p : model.path) {
    p.z() = 0.3;
  }
  EXPECT_DOUBLE_EQ(floorHeight(model), 0.3);
  model.path.clear();
  EXPECT_DOUBLE_EQ(floorHeight(model), 0.0);
  EXPECT_DOUBLE_EQ(floorHeight(products::MapModel{}), 0.0);
  MapViewOptions o;
  EXPECT_TRUE(o.validate().empty());
  o.fov_deg = 5;
  EXPECT_NE(o.validate().find("fov_deg"), std::string::npos);
}

}  // namespace
}  // namespace pmap::report
