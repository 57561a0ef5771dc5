#include "pmap/poses/poses_file.h"

#include <gtest/gtest.h>
#include <mrpt/graphs/CNetworkOfPoses.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "pmap/common/error.h"
#include "rawlog_fixtures.h"

namespace pmap::poses {
namespace {
using mrpt::math::TPose3D;

TEST(PosesFile, RoundTrips) {
  const auto dir = testing::freshTestDir("poses_roundtrip");
  Trajectory t;
  t.append(1767225600.123456, TPose3D(1.5, -2.25, 0.0, 0.5, 0.0, 0.0));
  t.append(1767225600.323456, TPose3D(1.6, -2.25, 0.0, -3.1, 0.01, -0.02));
  writePosesFile(dir / "poses.txt", t);
  const Trajectory r = readPosesFile(dir / "poses.txt");
  ASSERT_EQ(r.size(), 2u);
  EXPECT_NEAR(r.poses()[1].t, 1767225600.323456, 1e-6);
  EXPECT_NEAR(r.poses()[1].pose.yaw, -3.1, 1e-8);
  EXPECT_NEAR(r.poses()[1].pose.roll, -0.02, 1e-8);
}

std::string errorOf(const std::string& text) {
  const auto dir = testing::freshTestDir("poses_bad");
  std::ofstream(dir / "p.txt") << text;
  try {
    readPosesFile(dir / "p.txt");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(PosesFile, RejectsMalformedFilesNamingTheLine) {
  EXPECT_NE(errorOf("# c\n1 2 3\n").find("p.txt:2: expected 7 numbers"), std::string::npos);
  EXPECT_NE(errorOf("1 0 0 0 nan 0 0\n").find("not a finite number"), std::string::npos);
  EXPECT_NE(errorOf("2 0 0 0 0 0 0\n1 0 0 0 0 0 0\n").find("p.txt:2: timestamp"),
            std::string::npos);
  EXPECT_NE(errorOf("1 0 0 0 0 0 0\n1 0 0 0 0 0 0\n").find("not after"), std::string::npos);
  EXPECT_NE(errorOf("# only a comment\n").find("no poses"), std::string::npos);
  EXPECT_THROW(readPosesFile("/nonexistent/poses.txt"), InputError);
}

// Issue 13, item 6: poses.tum in the TUM format ("t tx ty tz qx qy qz qw",
// unit quaternion) that trajectory tools read.
TEST(PosesFile, Item6_WritesTheTumFormat) {
  const auto dir = testing::freshTestDir("poses_tum");
  Trajectory t;
  t.append(1767225600.5, TPose3D(1.5, -2.25, 0.125, 0.5, 0.0, 0.0));
  t.append(1767225600.7, TPose3D(1.6, -2.25, 0.0, -3.1, 0.01, -0.02));
  writeTumFile(dir / "poses.tum", t);
  std::ifstream in(dir / "poses.tum");
  std::string line;
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') {
      continue;
    }
    std::istringstream fields(line);
    std::vector<double> v;
    double x;
    while (fields >> x) {
      v.push_back(x);
    }
    rows.push_back(v);
  }
  ASSERT_EQ(rows.size(), 2u);
  for (const auto& r : rows) {
    ASSERT_EQ(r.size(), 8u);
    EXPECT_NEAR(r[4] * r[4] + r[5] * r[5] + r[6] * r[6] + r[7] * r[7], 1.0, 1e-8);
  }
  EXPECT_NEAR(rows[0][0], 1767225600.5, 1e-6);
  EXPECT_NEAR(rows[0][3], 0.125, 1e-9);
  // A pure yaw: q = (0, 0, sin(yaw / 2), cos(yaw / 2)).
  EXPECT_NEAR(rows[0][6], std::sin(0.25), 1e-9);
  EXPECT_NEAR(rows[0][7], std::cos(0.25), 1e-9);
  // The yaw comes back from the quaternion of the second pose (with pitch and roll).
  const auto& q = rows[1];
  const double yaw =
      std::atan2(2 * (q[7] * q[6] + q[4] * q[5]), 1 - 2 * (q[5] * q[5] + q[6] * q[6]));
  EXPECT_NEAR(yaw, -3.1, 1e-6);
}

// Issue 15 item 6: poses.graph is read back by MRPT's own graph class with
// the same nodes, edges and information matrices.
TEST(PosesFile, Item15_GraphFileIsReadByMrpt) {
  const auto dir = testing::freshTestDir("poses_graph");
  PoseGraph graph;
  graph.addNode({0, 0, 0});
  graph.addNode({1.25, 0.5, 0.3});
  graph.addNode({2.5, -1.0, -2.9});
  Eigen::Matrix3d info;
  info << 400, 12, -3, 12, 900, 7, -3, 7, 3000;
  graph.addEdge({0, 1, {1.2, 0.45, 0.31}, info, false});
  graph.addEdge({1, 2, {1.0, -1.5, -3.0}, Eigen::Matrix3d::Identity() * 50.0, false});
  graph.addEdge({0, 2, {2.5, -1.0, -2.9}, Eigen::Matrix3d::Identity() * 2500.0, true});
  writeGraphFile(dir / "poses.graph", graph);

  mrpt::graphs::CNetworkOfPoses2DInf read;
  read.loadFromTextFile((dir / "poses.graph").string());
  ASSERT_EQ(read.nodes.size(), 3u);
  ASSERT_EQ(read.edges.size(), 3u);
  EXPECT_NEAR(read.nodes.at(1).x(), 1.25, 1e-9);
  EXPECT_NEAR(read.nodes.at(2).phi(), -2.9, 1e-9);
  const auto& e01 = read.edges.find({0, 1})->second;
  EXPECT_NEAR(e01.mean.y(), 0.45, 1e-9);
  EXPECT_NEAR(e01.mean.phi(), 0.31, 1e-9);
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(e01.cov_inv(r, c), info(r, c), 1e-6) << r << "," << c;
    }
  }
  EXPECT_NEAR(read.edges.find({0, 2})->second.cov_inv(2, 2), 2500.0, 1e-6);
}

}  // namespace
}  // namespace pmap::poses
