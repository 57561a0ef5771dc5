#include "pmap/sim/surface_textures.h"

#include <gtest/gtest.h>

namespace pmap::sim {
namespace {

TEST(SurfaceTextures, ValueNoiseIsBoundedSmoothAndDeterministic) {
  for (double x = -3.0; x < 3.0; x += 0.173) {
    for (double y = -2.0; y < 2.0; y += 0.311) {
      const float n = valueNoise(x, y, 4);
      EXPECT_GE(n, 0.0f);
      EXPECT_LT(n, 1.0f);
      EXPECT_EQ(n, valueNoise(x, y, 4));
      EXPECT_NEAR(n, valueNoise(x + 1e-4, y, 4), 1e-3);
    }
  }
}

TEST(SurfaceTextures, KindsMapToMaterials) {
  EXPECT_EQ(materialForSurfaceKind("wall"), Material::kWallPaint);
  EXPECT_EQ(materialForSurfaceKind("door"), Material::kWood);
  EXPECT_EQ(materialForSurfaceKind("ceiling"), Material::kCeilingTiles);
  EXPECT_EQ(materialForSurfaceKind("floor"), Material::kFloor);
  EXPECT_EQ(materialForSurfaceKind("jamb"), Material::kFrame);
  EXPECT_EQ(materialForSurfaceKind("room_wall"), Material::kRoomPaint);
  EXPECT_EQ(materialForClutterKind("bin"), Material::kPlastic);
  EXPECT_EQ(materialForClutterKind("pillar"), Material::kConcrete);
}

TEST(SurfaceTextures, ColoursAreInRangeAndTextured) {
  for (const Material m :
       {Material::kWallPaint, Material::kRoomPaint, Material::kWood, Material::kFrame,
        Material::kCeilingTiles, Material::kFloor, Material::kPlastic, Material::kConcrete}) {
    float lo = 1e9f;
    float hi = -1e9f;
    for (double u = 0.0; u < 2.0; u += 0.013) {
      const Eigen::Vector3f c = materialColour(m, u, 0.37 * u, 9);
      for (int k = 0; k < 3; ++k) {
        EXPECT_GE(c[k], 0.0f);
        EXPECT_LE(c[k], 255.0f);
      }
      lo = std::min(lo, c.sum());
      hi = std::max(hi, c.sum());
    }
    EXPECT_GT(hi - lo, 3.0f) << "material " << static_cast<int>(m) << " has no texture";
  }
}

}  // namespace
}  // namespace pmap::sim
