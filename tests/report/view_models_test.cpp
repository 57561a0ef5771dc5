#include "view_models.h"

#include <gtest/gtest.h>

#include "report_test_model.h"

namespace pmap::report::detail {
namespace {

TEST(ViewModels, CeilingsAreRemoved) {
  const auto model = test::corridor();
  const auto open = withoutCeilings(model, 0.0, 1.8);
  ASSERT_EQ(open.quads.size(), 3u);  // floor and walls, no ceiling
  for (const auto& q : open.quads) {
    EXPECT_NE(q.surface_id, 3);
  }
  EXPECT_EQ(open.fine.triangles.size(), 2u);                              // below the cut
  EXPECT_EQ(withoutCeilings(model, 0.0, 1.0).fine.triangles.size(), 1u);  // centroids 0.83, 1.17
  EXPECT_EQ(withoutCeilings(model, 0.0, 0.5).fine.triangles.size(), 0u);
  EXPECT_EQ(open.path.size(), model.path.size());
}

TEST(ViewModels, FootprintsOfWallsAndPath) {
  auto model = withoutCeilings(test::corridor(), 0.0, 1.8);
  const std::size_t before = model.fine.triangles.size();
  addFootprints(model, 0.1, Eigen::Vector3d(1, 0.5, 0));
  EXPECT_TRUE(model.path.empty());
  // two walls (2 triangles each) and the path strips
  EXPECT_GT(model.fine.triangles.size(), before + 4);
  ASSERT_EQ(model.fine.colors.size(), model.fine.vertices.size());
  // the first strip is the green wall's top, 10.1 m long at z = 2.5
  const Eigen::Vector3d& a = model.fine.vertices[4];
  const Eigen::Vector3d& b = model.fine.vertices[5];
  EXPECT_DOUBLE_EQ(a.z(), 2.5);
  EXPECT_NEAR((b - a).norm(), 10.1, 1e-9);
  EXPECT_NEAR(model.fine.colors[4].y(), 0.6f * 0.8f, 1e-6);  // darkened
  // the textured wall's strip has the texture's mean colour (magenta-ish)
  const Eigen::Vector3f c = model.fine.colors[8];
  EXPECT_GT(c.x(), c.y());
  EXPECT_GT(c.z(), c.y());
}

}  // namespace
}  // namespace pmap::report::detail
