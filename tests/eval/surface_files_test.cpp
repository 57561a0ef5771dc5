#include "pmap/eval/surface_files.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "pmap/common/error.h"

namespace pmap::eval {
namespace {
namespace fs = std::filesystem;

const std::string kHeader = "id,nx,ny,nz,offset,x0,y0,z0,x1,y1,z1,x2,y2,z2,x3,y3,z3,support";
const std::string kRow0 =
    "0,0.0,-1.0,0.0,-1.1,0.02,1.1,0.31,28.9,1.1,0.31,28.9,1.1,2.69,0.02,1.1,2.69,41234";
const std::string kRow1 = "3,0,0,1,0,0,0,0,2,0,0,2,1,0,0,1,0,7";

fs::path writeCsv(const std::string& name, const std::string& text) {
  const fs::path dir = fs::path(PMAP_TEST_TMP_DIR) / "surface_files" / name;
  fs::create_directories(dir);
  const fs::path path = dir / "surfaces.csv";
  std::ofstream(path) << text;
  return path;
}

/// The InputError message of reading `text`, empty if it reads.
std::string errorOf(const std::string& name, const std::string& text) {
  try {
    readMapSurfaces(writeCsv(name, text));
  } catch (const InputError& e) {
    return e.what();
  }
  return {};
}

TEST(SurfaceFiles, ReadsRows) {
  const auto s = readMapSurfaces(writeCsv("good", kHeader + "\n" + kRow0 + "\n" + kRow1 + "\n"));
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0].id, 0);
  EXPECT_EQ(s[0].normal, Eigen::Vector3d(0, -1, 0));
  EXPECT_DOUBLE_EQ(s[0].offset_m, -1.1);
  EXPECT_EQ(s[0].corners[2], Eigen::Vector3d(28.9, 1.1, 2.69));
  EXPECT_EQ(s[0].support, 41234);
  EXPECT_EQ(s[1].id, 3);
  EXPECT_EQ(s[1].corners[3], Eigen::Vector3d(0, 1, 0));
}

TEST(SurfaceFiles, HeaderOnlyIsAnEmptyMapAndCrlfIsAccepted) {
  EXPECT_TRUE(readMapSurfaces(writeCsv("empty", kHeader + "\n")).empty());
  EXPECT_EQ(readMapSurfaces(writeCsv("crlf", kHeader + "\r\n" + kRow1 + "\r\n")).size(), 1u);
}

TEST(SurfaceFiles, NearlyUnitNormalIsNormalisedWithItsOffset) {
  const auto s = readMapSurfaces(writeCsv("near_unit", kHeader + "\n" +
                                                           "1,0,0,1.0005,2.001,0,0,2,1,0,2,1,1,"
                                                           "2,0,1,2,5\n"));
  EXPECT_NEAR(s[0].normal.norm(), 1.0, 1e-15);
  EXPECT_NEAR(s[0].offset_m, 2.001 / 1.0005, 1e-12);
}

TEST(SurfaceFiles, MalformedLinesAreInputErrorsNamingTheLine) {
  const std::string h = kHeader + "\n";
  EXPECT_NE(errorOf("header", "id,nx\n" + kRow0).find("surfaces.csv:1: header"), std::string::npos);
  EXPECT_NE(errorOf("no_header", "").find(":1: header"), std::string::npos);
  EXPECT_NE(errorOf("columns", h + kRow1 + "\n3,0,0,1,0,0,0,0,2,0,0,2,1,0,0,1,0\n")
                .find("surfaces.csv:3: expected 18 comma-separated columns, got 17"),
            std::string::npos);
  EXPECT_NE(errorOf("nan", h + "3,0,0,nan,0,0,0,0,2,0,0,2,1,0,0,1,0,7\n")
                .find(":2: column 4 'nan' is not a finite number"),
            std::string::npos);
  EXPECT_NE(errorOf("inf", h + "3,0,0,1,0,0,0,0,2,0,0,2,1,0,0,inf,0,7\n").find(":2: column 16"),
            std::string::npos);
  EXPECT_NE(errorOf("empty_field", h + "3,0,0,1,,0,0,0,2,0,0,2,1,0,0,1,0,7\n").find(":2: column 5"),
            std::string::npos);
  EXPECT_NE(
      errorOf("not_unit", h + "3,0,0,1.01,0,0,0,0,2,0,0,2,1,0,0,1,0,7\n").find(":2: normal length"),
      std::string::npos);
  EXPECT_NE(errorOf("zero_normal", h + "3,0,0,0,0,0,0,0,2,0,0,2,1,0,0,1,0,7\n").find(":2: normal"),
            std::string::npos);
  EXPECT_NE(errorOf("neg_id", h + "-1,0,0,1,0,0,0,0,2,0,0,2,1,0,0,1,0,7\n").find(":2: id '-1'"),
            std::string::npos);
  EXPECT_NE(errorOf("frac_id", h + "1.5,0,0,1,0,0,0,0,2,0,0,2,1,0,0,1,0,7\n").find(":2: id"),
            std::string::npos);
  EXPECT_NE(errorOf("support", h + "3,0,0,1,0,0,0,0,2,0,0,2,1,0,0,1,0,x\n").find(":2: support"),
            std::string::npos);
  EXPECT_NE(errorOf("dup", h + kRow1 + "\n" + kRow0 + "\n" + kRow1 + "\n")
                .find(":4: duplicate surface id 3"),
            std::string::npos);
  EXPECT_NE(errorOf("blank", h + kRow1 + "\n\n" + kRow0 + "\n").find(":3: empty line"),
            std::string::npos);
}

TEST(SurfaceFiles, MissingFileIsAnInputError) {
  EXPECT_THROW(readMapSurfaces(fs::path(PMAP_TEST_TMP_DIR) / "no-such-dir" / "surfaces.csv"),
               InputError);
}

TEST(SurfaceFiles, PointSurfaceIdsMustBeRowsOrMinusOne) {
  const auto s = readMapSurfaces(writeCsv("ids", kHeader + "\n" + kRow1 + "\n"));
  MapPoints p;
  p.surface = {-1, 3, 3};
  EXPECT_NO_THROW(checkSurfaceIds(p, s, "points.ply"));
  p.surface.push_back(4);
  try {
    checkSurfaceIds(p, s, "points.ply");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("points.ply: vertex 3 has surface id 4"),
              std::string::npos);
  }
  p.surface = {-2};
  EXPECT_THROW(checkSurfaceIds(p, s, "points.ply"), InputError);
}

TEST(SurfaceFiles, MovedSurfaceKeepsItsPointsOnItsPlane) {
  MapSurface s;
  s.normal = Eigen::Vector3d(1, 1, 0).normalized();
  const Eigen::Vector3d on_plane(2, 0, 1);
  s.offset_m = s.normal.dot(on_plane);
  s.corners = {on_plane, on_plane, on_plane, on_plane};
  const Rigid2D motion{0.4, {1.5, -2.0}};
  const MapSurface m = movedSurface(s, motion);
  const Eigen::Vector3d q = motion.apply(on_plane);
  EXPECT_NEAR(m.normal.dot(q), m.offset_m, 1e-12);
  EXPECT_NEAR(m.normal.norm(), 1.0, 1e-12);
  EXPECT_NEAR((m.corners[2] - q).norm(), 0.0, 1e-12);
}

}  // namespace
}  // namespace pmap::eval
