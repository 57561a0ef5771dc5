#include "pmap/refine/seams.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "pmap/em/rectangle.h"

namespace pmap::refine {
namespace {

constexpr double kDegToRad = M_PI / 180.0;
constexpr int kSamples = 32;

struct Candidate {
  const SurfaceParams& params;
  em::Rectangle rect;
  std::array<Eigen::Vector3d, 4> corners;
};

// Edge k's coordinate along itself at corner k and corner k+1 (s for the
// u-edges 0 and 2, t for the v-edges 1 and 3).
std::array<double, 2> edgeRange(const SurfaceParams& p, int edge) {
  switch (edge) {
    case 0:
      return {p.bounds[kUMin], p.bounds[kUMax]};
    case 1:
      return {p.bounds[kVMin], p.bounds[kVMax]};
    case 2:
      return {p.bounds[kUMax], p.bounds[kUMin]};
    default:
      return {p.bounds[kVMax], p.bounds[kVMin]};
  }
}

// The sub-range of the edge p0-p1 (as fractions in [0, 1]) whose points,
// projected onto b's plane, lie within `slack` of b's rectangle; none if no
// sample does.
std::optional<std::array<double, 2>> besideRange(const Eigen::Vector3d& p0,
                                                 const Eigen::Vector3d& p1, const em::Rectangle& b,
                                                 double slack) {
  double lo = 2.0, hi = -1.0;
  for (int i = 0; i <= kSamples; ++i) {
    const double f = static_cast<double>(i) / kSamples;
    const Eigen::Vector3d p = p0 + (p1 - p0) * f;
    if (b.squaredDistance(p - b.normal * b.planeDistance(p)) <= slack * slack) {
      lo = std::min(lo, f);
      hi = std::max(hi, f);
    }
  }
  if (hi < lo) {
    return std::nullopt;
  }
  return std::array<double, 2>{lo, hi};
}

std::optional<Seam> seamOf(const Candidate& a, std::size_t ia, int e, const Candidate& b,
                           std::size_t ib, const RefineOptions& options) {
  const double min_along = std::cos(options.seam_max_edge_angle_deg * kDegToRad);
  const Eigen::Vector3d& p0 = a.corners[static_cast<std::size_t>(e)];
  const Eigen::Vector3d& p1 = a.corners[static_cast<std::size_t>((e + 1) % 4)];
  const Eigen::Vector3d line = a.rect.normal.cross(b.rect.normal).normalized();
  if (std::abs((p1 - p0).normalized().dot(line)) < min_along) {
    return std::nullopt;
  }
  const double d0 = distanceToIntersection(a.rect.normal, b.rect.normal, b.rect.offset, p0);
  const double d1 = distanceToIntersection(a.rect.normal, b.rect.normal, b.rect.offset, p1);
  if (d0 > options.seam_distance_m || d1 > options.seam_distance_m) {
    return std::nullopt;
  }
  const auto range = besideRange(p0, p1, b.rect, options.seam_distance_m);
  if (!range || ((*range)[1] - (*range)[0]) * (p1 - p0).norm() < options.seam_min_length_m) {
    return std::nullopt;
  }
  const std::array<double, 2> r = edgeRange(a.params, e);
  Seam s;
  s.surface = ia;
  s.edge = e;
  s.other = ib;
  s.along = {r[0] + (r[1] - r[0]) * (*range)[0], r[0] + (r[1] - r[0]) * (*range)[1]};
  s.distance_m = 0.5 * (d0 + d1);
  return s;
}

}  // namespace

double distanceToIntersection(const Eigen::Vector3d& n_a, const Eigen::Vector3d& n_b,
                              double offset_b, const Eigen::Vector3d& point) {
  const double sine = n_a.cross(n_b).norm();
  if (sine < 1e-9) {
    return std::numeric_limits<double>::infinity();
  }
  return std::abs(n_b.dot(point) - offset_b) / sine;
}

std::vector<Seam> findSeams(const std::vector<SurfaceParams>& surfaces,
                            const RefineOptions& options) {
  const double max_cos = std::cos(options.seam_min_angle_deg * kDegToRad);
  std::vector<Candidate> c;
  for (const SurfaceParams& s : surfaces) {
    c.push_back({s, s.toRectangle(), cornersOf(s)});
  }
  std::vector<Seam> seams;
  for (std::size_t a = 0; a < c.size(); ++a) {
    for (int e = 0; e < 4; ++e) {
      for (std::size_t b = 0; b < c.size(); ++b) {
        if (b == a || std::abs(c[a].rect.normal.dot(c[b].rect.normal)) > max_cos) {
          continue;
        }
        if (auto s = seamOf(c[a], a, e, c[b], b, options)) {
          seams.push_back(*s);
        }
      }
    }
  }
  return seams;
}

}  // namespace pmap::refine
