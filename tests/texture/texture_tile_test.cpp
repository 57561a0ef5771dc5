#include "pmap/texture/texture_tile.h"

#include <gtest/gtest.h>

#include "synthetic_views.h"

namespace pmap::texture {
namespace {

TEST(TextureTile, LongWallIsCutIntoTilesThatCoverItExactly) {
  const products::TexturedQuad wall = test::wallQuad(7, 0.0, 31.0, 2.0, 2.7);
  TextureOptions o;  // 200 px/m, max side 2048: 6200 px -> 4 tiles along u
  const std::vector<TextureTile> tiles = planTiles({wall}, o);
  ASSERT_EQ(tiles.size(), 4u);
  double length = 0;
  for (std::size_t i = 0; i < tiles.size(); ++i) {
    EXPECT_EQ(tiles[i].surface_id, 7);
    EXPECT_EQ(tiles[i].tile, static_cast<int>(i));
    EXPECT_LE(tiles[i].width, 2048);
    EXPECT_EQ(tiles[i].height, 540);
    EXPECT_NEAR(tiles[i].origin.x(), length, 1e-9);
    EXPECT_NEAR(tiles[i].width / tiles[i].length_u, 200.0, 0.1);
    length += tiles[i].length_u;
  }
  EXPECT_NEAR(length, 31.0, 1e-9);
  EXPECT_TRUE(tiles[0].normal.isApprox(wall.normal));
}

TEST(TextureTile, TexelCentresFollowTheTextureConvention) {
  TextureTile t;
  t.origin = {0, 0, 0};
  t.u = Eigen::Vector3d::UnitX();
  t.v = Eigen::Vector3d::UnitZ();
  t.length_u = 1.0;
  t.length_v = 0.5;
  t.width = 10;
  t.height = 5;
  // Row 0 is the top edge (t = 1), column 0 the c0-c3 edge.
  EXPECT_TRUE(t.texelCentre(0, 0).isApprox(Eigen::Vector3d(0.05, 0, 0.45)));
  EXPECT_TRUE(t.texelCentre(9, 4).isApprox(Eigen::Vector3d(0.95, 0, 0.05)));
  const products::TexturedQuad q = t.quad();
  EXPECT_TRUE(q.corners[2].isApprox(Eigen::Vector3d(1, 0, 0.5)));
}

TEST(TextureTile, TotalBudgetLowersTheResolutionUniformly) {
  TextureOptions o;
  o.max_total_mpx = 0.5;  // 31 m x 2.7 m at 200 px/m would be 3.3 Mpx
  const std::vector<TextureTile> tiles = planTiles({test::wallQuad(1, 0, 31, 0, 2.7)}, o);
  long long texels = 0;
  for (const auto& t : tiles) {
    texels += 1LL * t.width * t.height;
  }
  EXPECT_LE(texels, 510000);
  EXPECT_GE(texels, 480000);
}

TEST(TextureTile, ThinAndDegenerateQuads) {
  TextureOptions o;
  const std::vector<TextureTile> thin = planTiles({test::wallQuad(1, 0, 1, 0, 0.001)}, o);
  ASSERT_EQ(thin.size(), 1u);
  EXPECT_EQ(thin[0].height, 1);
  EXPECT_TRUE(planTiles({test::wallQuad(2, 0, 0, 0, 1)}, o).empty());  // zero width
  EXPECT_TRUE(planTiles({}, o).empty());
}

// Issue 13, item 12: a thin quad 1e9 m long (geometry from bad poses) gets a
// bounded number of tiles of bounded size, not an int overflow.
TEST(TextureTile, Item12_AbsurdlyLongQuadGetsBoundedTiles) {
  TextureOptions o;
  const std::vector<TextureTile> tiles = planTiles({test::wallQuad(3, 0.0, 1e9, 0.0, 0.01)}, o);
  ASSERT_FALSE(tiles.empty());
  EXPECT_LE(tiles.size(), 4096u);
  double length = 0;
  for (const TextureTile& t : tiles) {
    EXPECT_GE(t.width, 1);
    EXPECT_LE(t.width, 2048);
    EXPECT_GE(t.height, 1);
    length += t.length_u;
  }
  EXPECT_NEAR(length, 1e9, 1.0);
}

}  // namespace
}  // namespace pmap::texture
