#include "pmap/texture/view_geometry.h"

#include <gtest/gtest.h>

#include "synthetic_views.h"

namespace pmap::texture {
namespace {

TEST(ViewGeometry, PolygonInsideTheViewIsKept) {
  const CameraFrame f = test::lookAt({0, 0, 1}, {0, 1, 0}, {0, 0, 1}, "c");
  const std::vector<Eigen::Vector3d> small = {{-0.1, 2, 0.9}, {0.1, 2, 0.9}, {0.1, 2, 1.1}};
  EXPECT_EQ(clipToView(small, f, 0).size(), 3u);
  const std::vector<Eigen::Vector3d> behind = {{-0.1, -2, 0.9}, {0.1, -2, 0.9}, {0.1, -2, 1.1}};
  EXPECT_TRUE(clipToView(behind, f, 0).empty());
}

TEST(ViewGeometry, LargePolygonIsClippedToTheImage) {
  const CameraFrame f = test::lookAt({0, 0, 1}, {0, 1, 0}, {0, 0, 1}, "c");
  const auto wall = test::wallQuad(0, -50, 50, 2, 50).corners;
  const auto clipped = clipToView({wall.begin(), wall.end()}, f, 0);
  ASSERT_GE(clipped.size(), 4u);
  for (const Eigen::Vector3d& c : clipped) {  // every vertex projects inside the image
    const double u = 320 * c.x() / c.z() + 319.5, v = 320 * c.y() / c.z() + 239.5;
    EXPECT_GE(u, -0.5 - 1e-6);
    EXPECT_LE(u, 639.5 + 1e-6);
    EXPECT_GE(v, -0.5 - 1e-6);
    EXPECT_LE(v, 479.5 + 1e-6);
  }
}

TEST(ViewGeometry, VisibleTexelsCoverWhatTheCameraSeesAndNoMore) {
  // Wall 2 m ahead; 90 degree field of view: x in [-2, 2] visible.
  const CameraFrame f = test::lookAt({10, 0, 1}, {0, 1, 0}, {0, 0, 1}, "c");
  TextureOptions o;
  const TextureTile tile = planTiles({test::wallQuad(0, 0, 20, 2, 2.5)}, o)[0];  // first 2048 px
  const TexelBox box = visibleTexels(tile, f, 6.0);
  ASSERT_FALSE(box.empty());
  // Projected texels outside the box are outside the image.
  for (int col = 0; col < tile.width; col += 7) {
    const auto px = f.project(tile.texelCentre(col, tile.height / 2));
    const bool inside = px && px->x() >= 0 && px->x() <= 639;
    if (inside) {
      EXPECT_GE(col, box.col0);
      EXPECT_LE(col, box.col1);
    }
  }
  EXPECT_TRUE(visibleTexels(tile, f, 1.0).empty());  // wall beyond the distance limit
}

}  // namespace
}  // namespace pmap::texture
