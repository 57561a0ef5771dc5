// A synthetic corridor for the micro-benchmarks: vertical scans across a
// 2.2 m wide, 2.7 m high corridor (the simulator's robot: 181 beams over
// 180 degrees from 0.3 m height, one scan every 8 cm), Gaussian range noise,
// and the three rectangles (two walls and the ceiling) that explain it.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <random>
#include <vector>

#include "pmap/em/neighbours.h"
#include "pmap/em/surface.h"

namespace pmap::bench {

struct Corridor {
  std::vector<Eigen::Vector3d> points;
  std::vector<em::GridKey> keys;        ///< group 0, row = scan, col = beam
  std::vector<std::size_t> scan_start;  ///< first point of each scan, plus the end
  std::vector<em::Surface> surfaces;
};

inline Corridor makeCorridor(int scans, double sigma_m = 0.02, std::uint64_t seed = 1) {
  constexpr double kHalfWidth = 1.1, kHeight = 2.7, kSensorZ = 0.3, kStep = 0.08;
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> noise(0.0, sigma_m);
  Corridor c;
  for (int s = 0; s < scans; ++s) {
    c.scan_start.push_back(c.points.size());
    const double x = kStep * s;
    for (int b = 0; b < 181; ++b) {
      const double a = M_PI * b / 180.0;  // 0: right (-y), 90 deg: up, 180 deg: left
      const Eigen::Vector2d dir(-std::cos(a), std::sin(a));
      double range = 1e9;
      if (std::abs(dir.x()) > 1e-9)
        range = std::min(range, kHalfWidth / std::abs(dir.x()));
      if (dir.y() > 1e-9)
        range = std::min(range, (kHeight - kSensorZ) / dir.y());
      range += noise(rng);
      c.points.emplace_back(x, range * dir.x(), kSensorZ + range * dir.y());
      c.keys.push_back({0, s, b});
    }
  }
  c.scan_start.push_back(c.points.size());
  const double length = kStep * std::max(scans - 1, 1);
  const auto wall = [&](double y) {
    em::Surface s;
    s.rect.normal = Eigen::Vector3d(0, y > 0 ? -1 : 1, 0);
    s.rect.offset = s.rect.normal.y() * y;
    s.rect.centre = Eigen::Vector3d(length / 2, y, (kSensorZ + kHeight) / 2);
    s.rect.axis_u = Eigen::Vector3d::UnitX();
    s.rect.half_u = length / 2;
    s.rect.half_v = (kHeight - kSensorZ) / 2;
    return s;
  };
  c.surfaces = {wall(-kHalfWidth), wall(kHalfWidth)};
  em::Surface ceiling;
  ceiling.rect.normal = -Eigen::Vector3d::UnitZ();
  ceiling.rect.offset = -kHeight;
  ceiling.rect.centre = Eigen::Vector3d(length / 2, 0, kHeight);
  ceiling.rect.axis_u = Eigen::Vector3d::UnitX();
  ceiling.rect.half_u = length / 2;
  ceiling.rect.half_v = kHalfWidth;
  c.surfaces.push_back(ceiling);
  for (int k = 0; k < 3; ++k)
    c.surfaces[static_cast<std::size_t>(k)].id = k;
  return c;
}

}  // namespace pmap::bench
