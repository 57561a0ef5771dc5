// planar-mapper --gui's window (LiveView): the camera framing of the final
// map, and, in a real X server (CTest runs this binary under xvfb-run), the
// window's scene objects kept for its whole life and the window's teardown.
#include "pmap/mapper/live_view.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

namespace pmap::mapper {
namespace {

constexpr double kFovDeg = 30.0;

/// A robot driving along x, seeing a vertical line of points 2 m to its left.
points::PointMap corridorMap(int scans) {
  points::PointMap map;
  for (int i = 0; i < scans; ++i) {
    input::StructureScan scan;
    scan.index = i;
    scan.cols = 5;
    for (int k = 0; k < 5; ++k) {
      scan.points.emplace_back(0.0, 2.0, 0.5 * k);
      scan.beams.push_back(k);
    }
    map.addScan(scan, mrpt::math::TPose3D(0.5 * i, 0.0, 0.0, 0.0, 0.0, 0.0));
  }
  return map;
}

products::TexturedQuad wall(double x0, double x1, bool textured) {
  products::TexturedQuad q;
  q.surface_id = static_cast<std::int32_t>(x0);
  q.corners = {Eigen::Vector3d(x0, 2, 0), Eigen::Vector3d(x1, 2, 0), Eigen::Vector3d(x1, 2, 2.5),
               Eigen::Vector3d(x0, 2, 2.5)};
  q.normal = -Eigen::Vector3d::UnitY();
  if (textured) {
    q.texture = cv::Mat(8, 8, CV_8UC3, cv::Scalar(40, 120, 200));
  }
  return q;
}

/// Two walls, one textured, and the path: the final map of corridorMap(n).
products::MapModel corridorModel(const points::PointMap& map) {
  products::MapModel model;
  model.quads = {wall(0, 10, true), wall(10, 20, false)};
  for (const auto& s : map.scans()) {
    model.path.emplace_back(s.robot_pose.x, s.robot_pose.y, s.robot_pose.z);
  }
  return model;
}

bool hasDisplay() {
  const char* d = std::getenv("DISPLAY");
  return d != nullptr && *d != '\0';
}

TEST(LiveView, Item10_FrameBoxLooksAtTheCentreFromFarEnough) {
  const Eigen::AlignedBox3d box(Eigen::Vector3d(-4, 2, 0), Eigen::Vector3d(16, 12, 3));
  const CameraFraming f = frameBox(box, kFovDeg);
  EXPECT_TRUE(f.target.isApprox(Eigen::Vector3d(6, 7, 1.5)));
  const double radius = 0.5 * box.diagonal().norm();
  // The sphere around the box fits the field of view, with the 10 % margin.
  EXPECT_NEAR(f.distance_m * std::sin(0.5 * kFovDeg * M_PI / 180.0), 1.1 * radius, 1e-9);
  // A larger map: farther away.
  const Eigen::AlignedBox3d twice(box.min() * 2, box.max() * 2);
  EXPECT_GT(frameBox(twice, kFovDeg).distance_m, 1.9 * f.distance_m);
}

TEST(LiveView, Item10_FrameBoxOfNothingOrOfAPoint) {
  const CameraFraming empty = frameBox(Eigen::AlignedBox3d(), kFovDeg);
  EXPECT_TRUE(empty.target.isZero());
  EXPECT_DOUBLE_EQ(empty.distance_m, 3.0);
  const Eigen::Vector3d p(1, 2, 3);
  const CameraFraming point = frameBox(Eigen::AlignedBox3d(p, p), kFovDeg);
  EXPECT_TRUE(point.target.isApprox(p));
  EXPECT_DOUBLE_EQ(point.distance_m, 3.0);
}

TEST(LiveView, Item10_MapBoundsAreTheMapNotTheStrayPoints) {
  points::PointMap map = corridorMap(4);
  input::StructureScan far;
  far.cols = 1;
  far.points = {Eigen::Vector3d(0, 80, 0)};  // a stray return far away
  far.beams = {0};
  map.addScan(far, mrpt::math::TPose3D(0, 0, 0, 0, 0, 0));
  const products::MapModel model = corridorModel(map);
  const Eigen::AlignedBox3d box = mapBounds(model, map);
  EXPECT_TRUE(box.min().isApprox(Eigen::Vector3d(0, 0, 0)));
  EXPECT_TRUE(box.max().isApprox(Eigen::Vector3d(20, 2, 2.5)));
  // No map (mapping stopped before the EM): the points are what is shown.
  const Eigen::AlignedBox3d points_box = mapBounds(products::MapModel{}, map);
  EXPECT_DOUBLE_EQ(points_box.max().y(), 80.0);
}

TEST(LiveView, Item1_SceneObjectsStayForTheWindowsWholeLife) {
  ASSERT_TRUE(hasDisplay()) << "needs an X display: run under xvfb-run";
  const points::PointMap map = corridorMap(12);
  LiveViewOptions options;
  options.hold_s = 0.0;
  LiveView view(options);
  view.update(map, 0, nullptr);
  const LiveViewState first = view.state();
  ASSERT_FALSE(first.objects.empty());
  EXPECT_EQ(first.scan_points, 5u);
  EXPECT_EQ(first.map_points, map.size());
  for (std::size_t r = 1; r < map.scans().size(); ++r) {
    view.update(map, r, nullptr);
    const LiveViewState s = view.state();
    EXPECT_EQ(s.objects, first.objects) << "update " << r << " replaced scene objects";
    EXPECT_EQ(s.path_segments, r);
    EXPECT_EQ(s.loop_segments, r / 5) << "update " << r;
    if (r % 5 == 4) {  // issue 15: a loop closure every fifth scan
      std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> loops;
      for (std::size_t k = 0; k <= r / 5; ++k) {
        loops.emplace_back(Eigen::Vector3d(0.5 * k, 0, 0.1), Eigen::Vector3d(0.5 * k, 1, 0.1));
      }
      view.setLoops(std::move(loops));
    }
  }
  view.finish(corridorModel(map), map);
  const LiveViewState last = view.state();
  EXPECT_EQ(last.objects, first.objects);
  EXPECT_EQ(last.textured_objects, 1u);
  EXPECT_EQ(last.surface_triangles, 2u);  // the untextured wall
  EXPECT_EQ(last.map_points, 0u);         // a map: no points
}

TEST(LiveView, Item10_FinishFramesTheWholeMap) {
  ASSERT_TRUE(hasDisplay()) << "needs an X display: run under xvfb-run";
  const points::PointMap map = corridorMap(12);
  LiveViewOptions options;
  options.hold_s = 0.0;
  LiveView view(options);
  view.update(map, map.scans().size() - 1, nullptr);
  const products::MapModel model = corridorModel(map);
  view.finish(model, map);
  const LiveViewState s = view.state();
  const CameraFraming expected = frameBox(mapBounds(model, map), kFovDeg);
  EXPECT_TRUE(s.camera_target.isApprox(expected.target.cast<float>(), 1e-5f));
  EXPECT_NEAR(s.camera_distance_m, expected.distance_m, 1e-3);
  EXPECT_GT(s.camera_distance_m, 20.0f);  // the whole 20 m corridor, not the last pose
}

TEST(LiveView, Item1_WindowsOpenAndCloseOneAfterAnother) {
  ASSERT_TRUE(hasDisplay()) << "needs an X display: run under xvfb-run";
  const points::PointMap map = corridorMap(6);
  for (int i = 0; i < 4; ++i) {
    LiveViewOptions options;
    options.hold_s = 0.0;
    LiveView view(options);
    for (std::size_t r = 0; r < map.scans().size(); ++r) {
      view.update(map, r, nullptr);
    }
    view.finish(corridorModel(map), map);
  }  // each window is closed and its GL canvas gone before the next opens
}

}  // namespace
}  // namespace pmap::mapper
