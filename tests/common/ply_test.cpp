#include "pmap/common/ply.h"

#include <gtest/gtest.h>

#include <fstream>

#include "pmap/common/error.h"

namespace pmap {
namespace {
namespace fs = std::filesystem;

fs::path dir(const std::string& name) {
  const fs::path d = fs::path(PMAP_TEST_TMP_DIR) / name;
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

TEST(Ply, BinaryRoundTrip) {
  const auto d = dir("ply_roundtrip");
  const std::vector<double> x = {1.5, -2.25, 3.0};
  const std::vector<double> id = {-1, 7, 123456};
  writePlyVertices(d / "a.ply", {{"x", "float", &x}, {"surface", "int", &id}});
  const PlyVertices v = readPlyVertices(d / "a.ply");
  ASSERT_EQ(v.size(), 3u);
  EXPECT_EQ(v.names, (std::vector<std::string>{"x", "surface"}));
  EXPECT_DOUBLE_EQ(v.columns[0][1], -2.25);
  EXPECT_DOUBLE_EQ(v.columns[1][2], 123456);
  EXPECT_DOUBLE_EQ(v.columns[1][0], -1);
}

TEST(Ply, ReadsAsciiAndSkipsOtherElements) {
  const auto d = dir("ply_ascii");
  std::ofstream(d / "a.ply") << "ply\nformat ascii 1.0\ncomment hi\nelement vertex 2\n"
                                "property double x\nproperty double y\nproperty double z\n"
                                "property uchar red\nelement face 1\n"
                                "property list uchar int vertex_indices\nend_header\n"
                                "0 1 2 255\n3 4 5 0\n3 0 1 1\n";
  const PlyVertices v = readPlyVertices(d / "a.ply");
  ASSERT_EQ(v.size(), 2u);
  EXPECT_EQ(v.find("z"), 2);
  EXPECT_DOUBLE_EQ(v.columns[2][1], 5);
  EXPECT_DOUBLE_EQ(v.columns[3][0], 255);
}

TEST(Ply, BadFilesAreInputErrors) {
  const auto d = dir("ply_bad");
  std::ofstream(d / "nomagic.ply") << "plx\n";
  std::ofstream(d / "huge.ply") << "ply\nformat binary_little_endian 1.0\nelement vertex "
                                   "99999999999\nproperty float x\nend_header\n";
  std::ofstream(d / "short.ply") << "ply\nformat ascii 1.0\nelement vertex 3\nproperty float "
                                    "x\nend_header\n1\n2\n";
  std::ofstream(d / "noend.ply") << "ply\nformat ascii 1.0\n";
  for (const char* f : {"nomagic.ply", "huge.ply", "short.ply", "noend.ply", "missing.ply"}) {
    EXPECT_THROW(readPlyVertices(d / f), InputError) << f;
  }
}

}  // namespace
}  // namespace pmap
