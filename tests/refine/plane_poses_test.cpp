// Planes correct poses (plane_poses.h): the correction's interpolation, and
// the fit on a synthetic room whose scans were placed with drifted poses.
#include "pmap/refine/plane_poses.h"

#include <gtest/gtest.h>
#include <mrpt/core/bits_math.h>

#include <cmath>
#include <random>

namespace pmap::refine {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A 12 x 5 m room (walls x = 0, x = 12, y = 0, y = 5), driven along y = 2.5
// from x = 1 to x = 11 at 0.5 m/s, a scan every 0.2 s.
struct Room {
  std::vector<mrpt::math::TPose3D> truth;
  std::vector<double> t;
  em::PlanarMap planar;
  points::PointMap map;
};

mrpt::math::TPose3D truePose(double t) {
  return {1.0 + 0.5 * t, 2.5 + 0.3 * std::sin(0.4 * t), 0.0, 0.12 * std::cos(0.4 * t), 0, 0};
}

// A pose error that grows along the run: `scale` * (4 cm, -3 cm, 0.4 deg)
// at the end, none at the start.
mrpt::math::TPose3D drifted(const mrpt::math::TPose3D& p, double t, double end_t, double scale) {
  const double f = scale * (t / end_t) * (t / end_t);
  mrpt::math::TPose3D out = p;
  out.x += 0.04 * f;
  out.y -= 0.03 * f;
  out.yaw += mrpt::DEG2RAD(0.4) * f;
  return out;
}

// Each scan sees every wall: 40 points per wall spread over the wall's
// length and over heights 0.5-2.5 m (a synthetic sensor, not a laser), with
// Gaussian noise sigma along the wall's normal.
Room makeRoom(double drift_scale, double sigma_m, unsigned seed) {
  Room room;
  const Eigen::Vector3d normals[4] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}};
  const double offsets[4] = {0.0, -12.0, 0.0, -5.0};  // n . p = offset
  for (int w = 0; w < 4; ++w) {
    em::Surface s;
    s.id = w;
    s.rect.normal = normals[w];
    s.rect.offset = offsets[w];
    s.rect.centre = w < 2 ? Eigen::Vector3d(w == 0 ? 0.0 : 12.0, 2.5, 1.5)
                          : Eigen::Vector3d(6.0, w == 2 ? 0.0 : 5.0, 1.5);
    room.planar.surfaces.push_back(s);
  }
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, sigma_m);
  std::uniform_real_distribution<double> along(0.05, 0.95), height(0.5, 2.5);
  const int scans = 101;
  const double end_t = 0.2 * (scans - 1);
  for (int i = 0; i < scans; ++i) {
    const double t = 0.2 * i;
    const mrpt::math::TPose3D truth = truePose(t);
    input::StructureScan scan;
    scan.index = i;
    scan.timestamp = t;
    scan.cols = 160;
    const double c = std::cos(truth.yaw), s = std::sin(truth.yaw);
    for (int w = 0; w < 4; ++w) {
      for (int j = 0; j < 40; ++j) {
        const double u = along(rng);
        Eigen::Vector3d p = w < 2 ? Eigen::Vector3d(w == 0 ? 0.0 : 12.0, 5.0 * u, height(rng))
                                  : Eigen::Vector3d(12.0 * u, w == 2 ? 0.0 : 5.0, height(rng));
        p += noise(rng) * normals[w];
        const Eigen::Vector2d d(p.x() - truth.x, p.y() - truth.y);
        scan.points.emplace_back(c * d.x() + s * d.y(), -s * d.x() + c * d.y(), p.z());
        scan.beams.push_back(w * 40 + j);
        room.planar.assignment.push_back(w);
      }
    }
    room.map.addScan(scan, drifted(truth, t, end_t, drift_scale));
    room.truth.push_back(truth);
    room.t.push_back(t);
  }
  return room;
}

PlanePoseOptions fitOptions() {
  PlanePoseOptions o;
  o.enabled = true;
  o.sigma_m = 0.01;
  o.points_per_scan_surface = 40;
  o.absolute_sigma_m = 0.0;  // the gauge and the motion priors only
  return o;
}

double worstError(const Room& room, const PoseCorrection& c) {
  double worst = 0;
  for (std::size_t i = 0; i < room.map.scans().size(); ++i) {
    const mrpt::math::TPose3D p = c.apply(room.t[i], room.map.scans()[i].robot_pose);
    worst = std::max(worst, std::hypot(p.x - room.truth[i].x, p.y - room.truth[i].y));
  }
  return worst;
}

TEST(PoseCorrection, InterpolatesLinearlyInTimeAndHoldsAtTheEnds) {
  const PoseCorrection c({1.0, 3.0},
                         {Eigen::Vector3d(0.1, 0.0, 0.0), Eigen::Vector3d(0.3, -0.2, 0.02)});
  EXPECT_TRUE(c.at(0.0).isApprox(Eigen::Vector3d(0.1, 0.0, 0.0)));
  EXPECT_TRUE(c.at(2.0).isApprox(Eigen::Vector3d(0.2, -0.1, 0.01)));
  EXPECT_TRUE(c.at(9.0).isApprox(Eigen::Vector3d(0.3, -0.2, 0.02)));
  EXPECT_TRUE(PoseCorrection().at(1.0).isZero());
}

TEST(PoseCorrection, TurnsAPoseAboutItsOwnPositionAndWraps) {
  const PoseCorrection c({0.0}, {Eigen::Vector3d(0.5, -0.25, 0.2)});
  const mrpt::math::TPose3D p = c.apply(0.0, {2.0, 3.0, 1.0, kPi - 0.1, 0.01, 0.02});
  EXPECT_NEAR(p.x, 2.5, 1e-12);
  EXPECT_NEAR(p.y, 2.75, 1e-12);
  EXPECT_NEAR(p.z, 1.0, 1e-12);
  EXPECT_NEAR(p.yaw, -kPi + 0.1, 1e-12);
  EXPECT_NEAR(p.pitch, 0.01, 1e-12);
}

TEST(PlanePoses, PosesOnTheirPlanesStayWhereTheyAre) {
  const Room room = makeRoom(0.0, 0.0, 1);
  const PlanePoseResult r = fitPosesToPlanes(room.map, room.planar, fitOptions());
  ASSERT_TRUE(r.ran);
  EXPECT_EQ(r.surfaces, 4);
  EXPECT_LT(r.max_shift_m, 1e-6);
  EXPECT_LT(r.max_turn_deg, 1e-5);
}

// (P1)-(P3): drifted scans come back to the walls; the points and the
// trajectory move with the correction.
TEST(PlanePoses, PullsDriftedScansBackOntoTheWalls) {
  Room room = makeRoom(1.0, 0.005, 2);
  ASSERT_GT(worstError(room, {}), 0.045);
  const PlanePoseResult r = fitPosesToPlanes(room.map, room.planar, fitOptions());
  ASSERT_TRUE(r.ran);
  EXPECT_EQ(r.termination, "CONVERGENCE");
  EXPECT_LT(worstError(room, r.correction), 0.005);
  EXPECT_GT(r.knots, 5);

  poses::Trajectory trajectory;
  for (std::size_t i = 0; i < room.t.size(); ++i) {
    trajectory.append(room.t[i], room.map.scans()[i].robot_pose);
  }
  applyCorrection(r.correction, room.map, trajectory);
  for (std::size_t i = 0; i < room.t.size(); i += 10) {
    EXPECT_NEAR(trajectory.poses()[i].pose.x, room.truth[i].x, 0.005);
    EXPECT_NEAR(room.map.scans()[i].robot_pose.y, room.truth[i].y, 0.005);
  }
  for (std::size_t i = 0; i < room.map.size(); i += 97) {  // every point back on its wall
    const em::Rectangle& wall = room.planar.surfaces[room.planar.assignment[i]].rect;
    EXPECT_LT(std::abs(wall.planeDistance(room.map.xyz()[i])), 0.03);
  }
}

// A second round starts from the first one's correction and keeps it.
TEST(PlanePoses, ARoundStartedFromACorrectionKeepsIt) {
  const Room room = makeRoom(1.0, 0.005, 3);
  const PlanePoseResult first = fitPosesToPlanes(room.map, room.planar, fitOptions());
  const PlanePoseResult second =
      fitPosesToPlanes(room.map, room.planar, fitOptions(), first.correction);
  ASSERT_TRUE(second.ran);
  for (std::size_t k = 0; k < first.correction.deltas().size(); ++k) {
    EXPECT_LT((first.correction.deltas()[k] - second.correction.deltas()[k]).norm(), 1e-4);
  }
}

TEST(PlanePoses, NothingToFitGivesNoCorrection) {
  Room room = makeRoom(0.0, 0.0, 4);
  em::PlanarMap ceilings = room.planar;
  for (em::Surface& s : ceilings.surfaces) {
    s.rect.normal = Eigen::Vector3d::UnitZ();  // no vertical surface
  }
  EXPECT_FALSE(fitPosesToPlanes(room.map, ceilings, fitOptions()).ran);
  em::PlanarMap wrong_size = room.planar;
  wrong_size.assignment.pop_back();
  EXPECT_FALSE(fitPosesToPlanes(room.map, wrong_size, fitOptions()).ran);
  points::PointMap one_scan;
  input::StructureScan scan;
  scan.points = {Eigen::Vector3d(1, 0, 1)};
  scan.beams = {0};
  one_scan.addScan(scan, {});
  em::PlanarMap one{room.planar.surfaces, {0}, {}};
  EXPECT_FALSE(fitPosesToPlanes(one_scan, one, fitOptions()).ran);
}

TEST(PlanePoseOptions, ValidateRejectsNonsense) {
  std::string why;
  EXPECT_TRUE(PlanePoseOptions().validate(&why));
  PlanePoseOptions o;
  o.knot_spacing_m = 0;
  EXPECT_FALSE(o.validate(&why));
  o = {};
  o.sigma_m = std::nan("");
  EXPECT_FALSE(o.validate(&why));
  o = {};
  o.max_normal_z = 1.0;
  EXPECT_FALSE(o.validate(&why));
  o = {};
  o.rounds = 0;
  EXPECT_FALSE(o.validate(&why));
  o = {};
  o.absolute_sigma_m = -1;
  EXPECT_FALSE(o.validate(&why));
  EXPECT_FALSE(why.empty());
}

}  // namespace
}  // namespace pmap::refine
