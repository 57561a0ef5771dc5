#include "pmap/scene/map_scene.h"

#include <gtest/gtest.h>
#include <mrpt/opengl/CPointCloud.h>
#include <mrpt/opengl/CPointCloudColoured.h>
#include <mrpt/opengl/CSetOfLines.h>
#include <mrpt/opengl/CSetOfObjects.h>
#include <mrpt/opengl/CSetOfTexturedTriangles.h>
#include <mrpt/opengl/CSetOfTriangles.h>

#include "pmap/common/error.h"
#include "scene_test_model.h"

namespace pmap::scene {
namespace {

using mrpt::opengl::CSetOfTexturedTriangles;
using mrpt::opengl::CSetOfTriangles;

TEST(MapScene, CountFollowsTheFormula) {
  const auto model = test::smallModel();
  const std::vector<Eigen::Vector3d> points(10, Eigen::Vector3d(1, 0, 1));
  SceneOptions o;
  o.points = &points;
  o.add_axes = true;
  const auto scene = buildMapScene(model, o);
  EXPECT_EQ(expectedObjectCount(model, o), 2u + 1u + 1u + 1u + 1u + 1u);
  EXPECT_EQ(countSceneObjects(*scene), expectedObjectCount(model, o));

  SceneOptions bare;
  bare.add_path = false;
  bare.add_grid = false;
  EXPECT_EQ(countSceneObjects(*buildMapScene(model, bare)), 3u);
  EXPECT_EQ(expectedObjectCount(model, bare), 3u);
}

TEST(MapScene, EmptyModelKeepsItsObjects) {
  const products::MapModel empty;
  const SceneOptions o;
  const auto scene = buildMapScene(empty, o);
  EXPECT_EQ(countSceneObjects(*scene), 3u);  // fine triangles, path, grid
  const auto fine = scene->getByClass<CSetOfTriangles>();
  ASSERT_TRUE(fine);
  EXPECT_EQ(fine->getTrianglesCount(), 0u);
}

TEST(MapScene, TexturedQuadUsesTheTextureConvention) {
  const auto scene = buildMapScene(test::smallModel(), SceneOptions{});
  const auto wall = scene->getByClass<CSetOfTexturedTriangles>();
  ASSERT_TRUE(wall);
  EXPECT_EQ(wall->getName(), "surface_3");
  EXPECT_EQ(wall->getTextureImage().getWidth(), 32u);
  EXPECT_EQ(wall->getTextureImage().getHeight(), 16u);
  ASSERT_EQ(wall->getTrianglesCount(), 2u);
  // Triangle c0 c1 c2: c0 is (s, t) = (0, 0), the image's last row: v = 1.
  const auto t = wall->getTriangle(0);
  EXPECT_FLOAT_EQ(t.u(0), 0.0f);
  EXPECT_FLOAT_EQ(t.v(0), 1.0f);
  EXPECT_FLOAT_EQ(t.u(1), 1.0f);
  EXPECT_FLOAT_EQ(t.v(1), 1.0f);
  EXPECT_FLOAT_EQ(t.u(2), 1.0f);
  EXPECT_FLOAT_EQ(t.v(2), 0.0f);
  EXPECT_FLOAT_EQ(t.vertices[0].normal.y, -1.0f);
}

TEST(MapScene, UntexturedQuadHasItsColourAndFineTrianglesTheirs) {
  const auto scene = buildMapScene(test::smallModel(), SceneOptions{});
  const auto floor = std::dynamic_pointer_cast<CSetOfTriangles>(scene->getByName("surface_7"));
  ASSERT_TRUE(floor);
  ASSERT_EQ(floor->getTrianglesCount(), 2u);
  mrpt::opengl::TTriangle floor_t;
  floor->getTriangle(0, floor_t);
  EXPECT_EQ(floor_t.r(0), 204);
  const auto fine =
      std::dynamic_pointer_cast<CSetOfTriangles>(scene->getByName(object_names::kFineTriangles));
  ASSERT_TRUE(fine);
  ASSERT_EQ(fine->getTrianglesCount(), 2u);
  mrpt::opengl::TTriangle t;
  fine->getTriangle(0, t);
  EXPECT_EQ(t.r(0), 255);
  EXPECT_EQ(t.g(1), 255);
  EXPECT_EQ(t.b(2), 255);
}

TEST(MapScene, PathIsALineStrip) {
  const auto scene = buildMapScene(test::smallModel(), SceneOptions{});
  const auto path =
      std::dynamic_pointer_cast<mrpt::opengl::CSetOfLines>(scene->getByName("robot_path"));
  ASSERT_TRUE(path);
  EXPECT_EQ(path->getLineCount(), 2u);
}

TEST(MapScene, PointsColouredOrPlain) {
  const std::vector<Eigen::Vector3d> points = {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 2, 3)};
  const std::vector<Eigen::Vector3f> colors(2, Eigen::Vector3f(1, 0, 0));
  SceneOptions o;
  o.points = &points;
  const auto plain = buildMapScene(products::MapModel{}, o);
  const auto cloud = plain->getByClass<mrpt::opengl::CPointCloud>();
  ASSERT_TRUE(cloud);
  EXPECT_EQ(cloud->size(), 2u);
  o.point_colors = &colors;
  const auto coloured = buildMapScene(products::MapModel{}, o);
  const auto ccloud = coloured->getByClass<mrpt::opengl::CPointCloudColoured>();
  ASSERT_TRUE(ccloud);
  EXPECT_EQ(ccloud->size(), 2u);
}

TEST(MapScene, CountsInsideSetsOfObjects) {
  auto scene = buildMapScene(test::smallModel(), SceneOptions{});
  const std::size_t before = countSceneObjects(*scene);
  auto set = mrpt::opengl::CSetOfObjects::Create();
  set->insert(CSetOfTriangles::Create());
  set->insert(CSetOfTriangles::Create());
  scene->insert(set);
  EXPECT_EQ(countSceneObjects(*scene), before + 2);
}

TEST(MapScene, RejectsBadOptionsAndBadModels) {
  SceneOptions o;
  o.grid_spacing_m = 0;
  EXPECT_NE(o.validate().find("grid_spacing_m"), std::string::npos);
  EXPECT_THROW(buildMapScene(test::smallModel(), o), ConfigError);

  const std::vector<Eigen::Vector3d> points(3, Eigen::Vector3d::Zero());
  const std::vector<Eigen::Vector3f> colors(2, Eigen::Vector3f::Zero());
  SceneOptions mismatch;
  mismatch.points = &points;
  mismatch.point_colors = &colors;
  EXPECT_THROW(buildMapScene(test::smallModel(), mismatch), ConfigError);

  auto bad = test::smallModel();
  bad.fine.triangles.push_back({0, 1, 99});
  EXPECT_THROW(buildMapScene(bad, SceneOptions{}), ProcessingError);

  auto float_texture = test::smallModel();
  float_texture.quads[0].texture = cv::Mat(4, 4, CV_32FC3, cv::Scalar(0.5, 0.5, 0.5));
  EXPECT_THROW(buildMapScene(float_texture, SceneOptions{}), ProcessingError);
}

TEST(MapScene, GreyAndAlphaTexturesBecomeBgr) {
  auto model = test::smallModel();
  model.quads[0].texture = cv::Mat(8, 8, CV_8UC1, cv::Scalar(100));
  model.quads[1].texture = cv::Mat(8, 8, CV_8UC4, cv::Scalar(1, 2, 3, 255));
  const auto scene = buildMapScene(model, SceneOptions{});
  for (std::size_t i = 0; i < 2; ++i) {
    const auto quad = scene->getByClass<CSetOfTexturedTriangles>(i);
    ASSERT_TRUE(quad);
    EXPECT_EQ(quad->getTextureImage().channelCount(), 3u);
  }
}

}  // namespace
}  // namespace pmap::scene
