#include "pmap/products/map_model_check.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "map_model_fixture.h"

namespace pmap::products {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

void expectRejected(const MapModel& m, const std::string& words) {
  try {
    checkMapModel(m);
    FAIL() << "accepted a model that breaks: " << words;
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
  }
}

TEST(MapModelCheck, AcceptsTheTestRoomAndAnEmptyModel) {
  EXPECT_NO_THROW(checkMapModel(test::texturedRoomModel()));
  EXPECT_NO_THROW(checkMapModel(MapModel{}));
}

TEST(MapModelCheck, AcceptsUntexturedQuadsWithoutIdsAndUncolouredTriangles) {
  MapModel m = test::texturedRoomModel();
  m.quads[3].surface_id = -1;
  m.quads.push_back(m.quads[3]);  // two untextured quads with id -1
  m.fine.colors.clear();
  EXPECT_NO_THROW(checkMapModel(m));
}

TEST(MapModelCheck, RejectsNonFiniteGeometry) {
  MapModel m = test::texturedRoomModel();
  m.quads[1].corners[2].y() = kNaN;
  expectRejected(m, "non-finite corner");
  m = test::texturedRoomModel();
  m.quads[0].normal.setZero();
  expectRejected(m, "normal");
  m = test::texturedRoomModel();
  m.fine.vertices[3].z() = std::numeric_limits<double>::infinity();
  expectRejected(m, "non-finite vertex");
  m = test::texturedRoomModel();
  m.fine.colors[0].x() = std::nanf("");
  expectRejected(m, "non-finite colour");
}

// map.glb draws the path as a line (its POSITION bounds must be finite).
TEST(MapModelCheck, Item10_RejectsANonFinitePathPosition) {
  MapModel m = test::texturedRoomModel();
  m.path[1].x() = kNaN;
  expectRejected(m, "path: non-finite position");
}

TEST(MapModelCheck, RejectsTextureNamingConflicts) {
  MapModel m = test::texturedRoomModel();
  m.quads[1].surface_id = m.quads[0].surface_id;
  expectRejected(m, "duplicate (surface_id, tile)");
  m.quads[1].tile = 1;  // another tile of the same surface
  EXPECT_NO_THROW(checkMapModel(m));
  m = test::texturedRoomModel();
  m.quads[2].surface_id = -1;
  expectRejected(m, "surface_id >= 0 and tile >= 0");
  m = test::texturedRoomModel();
  m.quads[2].tile = -1;
  expectRejected(m, "surface_id >= 0 and tile >= 0");
}

TEST(MapModelCheck, RejectsOtherTextureTypes) {
  MapModel m = test::texturedRoomModel();
  m.quads[0].texture = cv::Mat(4, 4, CV_32FC3, cv::Scalar(0.5, 0.5, 0.5));
  expectRejected(m, "CV_8UC3");
  m.quads[0].texture = cv::Mat(4, 4, CV_8UC1, cv::Scalar(7));
  expectRejected(m, "CV_8UC3");
}

TEST(MapModelCheck, RejectsBadTriangleIndicesAndColourCounts) {
  MapModel m = test::texturedRoomModel();
  m.fine.triangles.push_back({0, 1, 4});
  expectRejected(m, "index 4 out of range (4 vertices)");
  m = test::texturedRoomModel();
  m.fine.colors.pop_back();
  expectRejected(m, "3 colours for 4 vertices");
}

}  // namespace
}  // namespace pmap::products
