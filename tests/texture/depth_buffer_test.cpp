#include "pmap/texture/depth_buffer.h"

#include <gtest/gtest.h>

#include "synthetic_views.h"

namespace pmap::texture {
namespace {

TEST(DepthBuffer, NearerSurfaceHidesTheOneBehindIt) {
  const CameraFrame f = test::lookAt({0, 0, 1}, {0, 1, 0}, {0, 0, 1}, "c");
  TextureOptions o;
  std::vector<TextureTile> tiles =
      planTiles({test::wallQuad(1, -3, 3, 3, 3), test::wallQuad(2, -0.5, 0.5, 1.5, 3)}, o);
  const DepthBuffer depth(f, tiles, {}, 4);
  const Eigen::Vector3d back = f.world_to_camera * Eigen::Vector3d(0, 3, 1);
  const Eigen::Vector3d back_side = f.world_to_camera * Eigen::Vector3d(2, 3, 1);
  const Eigen::Vector3d front = f.world_to_camera * Eigen::Vector3d(0, 1.5, 1);
  EXPECT_TRUE(depth.hidden(back, 1, 0.05));
  EXPECT_FALSE(depth.hidden(back_side, 1, 0.05));
  EXPECT_FALSE(depth.hidden(front, 2, 0.05));
}

TEST(DepthBuffer, ASurfaceNeverHidesItselfEvenAtGrazingAngles) {
  const CameraFrame f = test::lookAt({0, 0, 1}, {1, 0.15, 0}, {0, 0, 1}, "c");
  TextureOptions o;
  const std::vector<TextureTile> tiles = planTiles({test::wallQuad(1, 0, 20, 1, 3)}, o);
  const DepthBuffer depth(f, tiles, {}, 4);
  for (double x = 2; x < 12; x += 0.37) {
    const Eigen::Vector3d c = f.world_to_camera * Eigen::Vector3d(x, 1, 1.2);
    EXPECT_FALSE(depth.hidden(c, 1, 0.0)) << x;
  }
}

TEST(DepthBuffer, FineTrianglesOccludeToo) {
  const CameraFrame f = test::lookAt({0, 0, 1}, {0, 1, 0}, {0, 0, 1}, "c");
  products::ColoredTriangles fine;
  fine.vertices = {{-0.3, 1.5, 0.7}, {0.3, 1.5, 0.7}, {0, 1.5, 1.4}};
  fine.triangles = {{0, 1, 2}};
  const DepthBuffer depth(f, {}, fine, 4);
  EXPECT_TRUE(depth.hidden(f.world_to_camera * Eigen::Vector3d(0, 3, 1), 1, 0.05));
  EXPECT_FALSE(depth.hidden(f.world_to_camera * Eigen::Vector3d(1.5, 3, 1), 1, 0.05));
  EXPECT_EQ(depth.owner(depth.cols() / 2, depth.rows() / 2), DepthBuffer::kFineTriangles);
}

}  // namespace
}  // namespace pmap::texture
