// map-eval's readers of the map directory (issue 13, item 12): points.ply
// must hold finite coordinates and whole ids; a directory is no file.
#include "pmap/eval/map_files.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>

#include "pmap/common/error.h"
#include "pmap/common/ply.h"

namespace pmap::eval {
namespace {
namespace fs = std::filesystem;

fs::path tmpDir() {
  const fs::path dir = fs::path(PMAP_TEST_TMP_DIR) / "map_files";
  fs::create_directories(dir);
  return dir;
}

/// A points.ply of three points, all columns double.
fs::path writePoints(const std::string& name, int bad_column, double bad_value) {
  std::vector<std::vector<double>> cols = {{0, 1, 2}, {0, 0, 0}, {1, 1, 1},
                                           {0, 0, 0}, {0, 1, 2}, {-1, 3, 3}};
  if (bad_column >= 0) {
    cols[static_cast<std::size_t>(bad_column)][1] = bad_value;
  }
  const char* names[] = {"x", "y", "z", "scan", "beam", "surface"};
  std::vector<PlyColumn> columns;
  for (std::size_t k = 0; k < 6; ++k) {
    columns.push_back({names[k], "double", &cols[k]});
  }
  writePlyVertices(tmpDir() / name, columns);
  return tmpDir() / name;
}

std::string errorOf(const fs::path& ply) {
  try {
    readMapPoints(ply);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(MapFiles, ReadsFinitePointsAndWholeIds) {
  const MapPoints p = readMapPoints(writePoints("good.ply", -1, 0));
  ASSERT_EQ(p.xyz.size(), 3u);
  EXPECT_EQ(p.surface[0], -1);
  EXPECT_EQ(p.beam[2], 2);
}

TEST(MapFiles, Item12_NonFiniteOrFractionalValuesAreInputErrorsNamingTheVertex) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const fs::path y = writePoints("nan_y.ply", 1, nan);
  EXPECT_EQ(errorOf(y), y.string() + ": vertex 1: y is nan, not a finite number");
  EXPECT_NE(errorOf(writePoints("inf_x.ply", 0, inf)).find("vertex 1: x is inf"),
            std::string::npos);
  EXPECT_NE(errorOf(writePoints("nan_scan.ply", 3, nan)).find("vertex 1: scan is nan"),
            std::string::npos);
  EXPECT_NE(errorOf(writePoints("half_beam.ply", 4, 0.5)).find("vertex 1: beam 0.5"),
            std::string::npos);
  EXPECT_NE(errorOf(writePoints("huge_surface.ply", 5, 1e12)).find("not an integer in int range"),
            std::string::npos);
}

TEST(MapFiles, Item12_ADirectoryIsNotAFile) {
  fs::create_directories(tmpDir() / "dir.ply");
  try {
    requireRegularFile(tmpDir() / "dir.ply");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              (tmpDir() / "dir.ply").string() + ": is a directory, not a file");
  }
  EXPECT_THROW(requireRegularFile(tmpDir() / "missing.ply"), InputError);
  std::ofstream(tmpDir() / "file.ply") << "x";
  EXPECT_NO_THROW(requireRegularFile(tmpDir() / "file.ply"));
}

}  // namespace
}  // namespace pmap::eval
