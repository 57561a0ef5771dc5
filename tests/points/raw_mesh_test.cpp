#include "pmap/points/raw_mesh.h"

#include <gtest/gtest.h>

namespace pmap::points {
namespace {

// A 2D "scan" of `n` beams on a line at height z, x = scan offset.
input::StructureScan lineScan(std::int64_t index, double x, int n, double spacing) {
  input::StructureScan s;
  s.index = index;
  s.label = "V";
  s.cols = n;
  for (int i = 0; i < n; ++i) {
    s.points.emplace_back(x, i * spacing, 2.0);
    s.beams.push_back(i);
  }
  return s;
}

TEST(RawMesh, TwoTrianglesPerQuadOfNeighbouringBeamsInConsecutiveScans) {
  PointMap map;
  RawMeshBuilder mesh;
  for (int k = 0; k < 3; ++k) {
    const auto scan = lineScan(k, 0.08 * k, 5, 0.05);
    mesh.addScan(map, map.addScan(scan, {}), 1, 5, true);
  }
  EXPECT_EQ(mesh.triangles().size(), 2u * 4u * 2u);  // 2 scan pairs x 4 quads x 2
}

TEST(RawMesh, SkipsQuadsWithAMissingBeamOrALongSide) {
  PointMap map;
  RawMeshBuilder mesh(RawMeshOptions{0.3});
  auto a = lineScan(0, 0.0, 5, 0.05);
  auto b = lineScan(1, 0.08, 5, 0.05);
  b.points.erase(b.points.begin() + 2);  // beam 2 invalid: quads 1-2 and 2-3 go
  b.beams.erase(b.beams.begin() + 2);
  mesh.addScan(map, map.addScan(a, {}), 1, 5, true);
  mesh.addScan(map, map.addScan(b, {}), 1, 5, true);
  EXPECT_EQ(mesh.triangles().size(), 2u * 2u);
  auto far = lineScan(2, 1.0, 5, 0.05);  // 0.92 m from the previous scan
  mesh.addScan(map, map.addScan(far, {}), 1, 5, true);
  EXPECT_EQ(mesh.triangles().size(), 4u);
}

TEST(RawMesh, SensorsAreMeshedSeparatelyAndCloudsNotAtAll) {
  PointMap map;
  RawMeshBuilder mesh;
  auto a = lineScan(0, 0.0, 4, 0.05);
  auto b = lineScan(1, 0.08, 4, 0.05);
  b.label = "OTHER";
  mesh.addScan(map, map.addScan(a, {}), 1, 4, true);
  mesh.addScan(map, map.addScan(b, {}), 1, 4, true);
  EXPECT_TRUE(mesh.triangles().empty());
  mesh.addScan(map, map.addScan(lineScan(2, 0.08, 4, 0.05), {}), 1, 4, false);
  EXPECT_TRUE(mesh.triangles().empty());
}

TEST(RawMesh, RangeImagesMeshNeighbouringPixels) {
  input::StructureScan s;
  s.rows = 3;
  s.cols = 4;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 4; ++c) {
      s.points.emplace_back(2.0, c * 0.01, r * 0.01);
      s.beams.push_back(r * 4 + c);
    }
  }
  PointMap map;
  RawMeshBuilder mesh;
  mesh.addScan(map, map.addScan(s, {}), 3, 4, true);
  EXPECT_EQ(mesh.triangles().size(), 2u * 2u * 3u);
}

TEST(RawMesh, SplitsAlongTheShorterDiagonal) {
  PointMap map;
  RawMeshBuilder mesh;
  input::StructureScan a;
  a.label = "V";
  a.cols = 2;
  a.points = {{0, 0, 0}, {0, 0.1, 0}};
  a.beams = {0, 1};
  input::StructureScan b = a;
  b.index = 1;
  b.points = {{0.1, 0.05, 0}, {0.1, 0.15, 0}};  // sheared: (0,0)-(0.1,0.15) is the long diagonal
  mesh.addScan(map, map.addScan(a, {}), 1, 2, true);
  mesh.addScan(map, map.addScan(b, {}), 1, 2, true);
  ASSERT_EQ(mesh.triangles().size(), 2u);
  // Quad a0 a1 b1 b0 = points 0 1 3 2; the shorter diagonal is a1-b0 (1-2).
  for (const auto& t : mesh.triangles()) {
    const bool has1 = t[0] == 1 || t[1] == 1 || t[2] == 1;
    const bool has2 = t[0] == 2 || t[1] == 2 || t[2] == 2;
    EXPECT_TRUE(has1 && has2);
  }
}

}  // namespace
}  // namespace pmap::points
