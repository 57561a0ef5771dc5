#include "pmap/refine/surface_params.h"

#include <gtest/gtest.h>

#include <random>

namespace pmap::refine {
namespace {

em::Rectangle randomRectangle(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  em::Rectangle r;
  r.normal = Eigen::Vector3d(u(rng), u(rng), u(rng)).normalized();
  r.centre = Eigen::Vector3d(u(rng), u(rng), u(rng)) * 5.0;
  r.offset = r.normal.dot(r.centre);
  r.axis_u = r.normal.unitOrthogonal();
  r.half_u = 0.5 + std::abs(u(rng));
  r.half_v = 0.2 + std::abs(u(rng));
  return r;
}

TEST(SurfaceParams, RoundTripReproducesTheRectangle) {
  std::mt19937 rng(3);
  for (int k = 0; k < 50; ++k) {
    const em::Rectangle r = randomRectangle(rng);
    const em::Rectangle back = SurfaceParams::fromRectangle(r).toRectangle();
    const auto a = r.corners();
    const auto b = back.corners();
    for (std::size_t i = 0; i < 4; ++i) {
      EXPECT_LT((a[i] - b[i]).norm(), 1e-12);
    }
    EXPECT_NEAR(back.offset, r.offset, 1e-12);
  }
}

TEST(SurfaceParams, CornersAndEdgePointsAgree) {
  std::mt19937 rng(4);
  SurfaceParams p = SurfaceParams::fromRectangle(randomRectangle(rng));
  p.rotation = 0.3;
  p.bounds = {-0.4, 1.2, -0.7, 0.5};
  const auto c = cornersOf(p);
  const Frame<double> f =
      frameOf(p.normal.data(), &p.offset, &p.rotation, p.ref_centre, p.ref_axis);
  // Edge k runs from corner k to corner k+1.
  const double starts[4] = {p.bounds[kUMin], p.bounds[kVMin], p.bounds[kUMax], p.bounds[kVMax]};
  const double ends[4] = {p.bounds[kUMax], p.bounds[kVMax], p.bounds[kUMin], p.bounds[kVMin]};
  for (int k = 0; k < 4; ++k) {
    EXPECT_LT((edgePoint(f, p.bounds.data(), k, starts[k]) - c[static_cast<std::size_t>(k)]).norm(),
              1e-12);
    EXPECT_LT((edgePoint(f, p.bounds.data(), k, ends[k]) - c[static_cast<std::size_t>((k + 1) % 4)])
                  .norm(),
              1e-12);
  }
  // The frame is orthonormal and right-handed, its origin on the plane.
  EXPECT_NEAR(f.u.norm(), 1.0, 1e-12);
  EXPECT_NEAR(f.u.dot(f.n), 0.0, 1e-12);
  EXPECT_LT((f.n.cross(f.u) - f.v).norm(), 1e-12);
  EXPECT_NEAR(f.n.dot(f.origin) - p.offset, 0.0, 1e-12);
}

TEST(SurfaceParams, CollapsedBoundsGiveAnEmptyRectangleNotANegativeOne) {
  std::mt19937 rng(5);
  SurfaceParams p = SurfaceParams::fromRectangle(randomRectangle(rng));
  p.bounds = {1.0, 0.5, 0.0, 1.0};
  EXPECT_EQ(p.toRectangle().half_u, 0.0);
}

}  // namespace
}  // namespace pmap::refine
