#include "pmap/eval/triangle_index.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace pmap::eval {
namespace {

Eigen::Vector3d closestOnSegment(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                 const Eigen::Vector3d& p) {
  const Eigen::Vector3d ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return a + t * ab;
}

/// Nearest of the three edges: the answer for a degenerate (flat) triangle.
Eigen::Vector3d closestOnEdges(const Triangle3& t, const Eigen::Vector3d& p) {
  const Eigen::Vector3d candidates[3] = {
      closestOnSegment(t.a, t.b, p), closestOnSegment(t.b, t.c, p), closestOnSegment(t.c, t.a, p)};
  const Eigen::Vector3d* best = &candidates[0];
  for (const Eigen::Vector3d& q : candidates) {
    if ((q - p).squaredNorm() < (*best - p).squaredNorm()) {
      best = &q;
    }
  }
  return *best;
}

constexpr int kBits = 21;
constexpr std::int64_t kOffset = std::int64_t{1} << (kBits - 1);
constexpr std::int64_t kMask = (std::int64_t{1} << kBits) - 1;

}  // namespace

Eigen::Vector3d closestPointOnTriangle(const Triangle3& t, const Eigen::Vector3d& p) {
  const Eigen::Vector3d ab = t.b - t.a, ac = t.c - t.a, ap = p - t.a;
  if (ab.isZero(0) && ac.isZero(0)) {
    return t.a;  // a point
  }
  if (ab.cross(ac).squaredNorm() <= 1e-24 * std::max(1.0, ab.squaredNorm() * ac.squaredNorm())) {
    return closestOnEdges(t, p);
  }
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0)
    return t.a;
  const Eigen::Vector3d bp = p - t.b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3)
    return t.b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0)
    return t.a + d1 / (d1 - d3) * ab;
  const Eigen::Vector3d cp = p - t.c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6)
    return t.c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0)
    return t.a + d2 / (d2 - d6) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    return t.b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (t.c - t.b);
  }
  const double denom = 1.0 / (va + vb + vc);
  return t.a + ab * (vb * denom) + ac * (vc * denom);
}

bool TriangleIndexOptions::validate(std::string* why) const {
  const auto fail = [why](const char* rule) {
    if (why != nullptr)
      *why = rule;
    return false;
  };
  if (!(cell_m > 0.0 && std::isfinite(cell_m)))
    return fail("cell_m must be > 0");
  if (!(max_distance_m > 0.0 && std::isfinite(max_distance_m))) {
    return fail("max_distance_m must be > 0");
  }
  if (max_distance_m / cell_m > 1000.0)
    return fail("max_distance_m / cell_m must be <= 1000");
  return true;
}

TriangleIndex::TriangleIndex(std::vector<Triangle3> triangles, const TriangleIndexOptions& options)
    : triangles_(std::move(triangles)), options_(options) {
  std::string why;
  if (!options_.validate(&why)) {
    throw std::invalid_argument("TriangleIndex: " + why);
  }
  for (std::uint32_t k = 0; k < triangles_.size(); ++k) {
    insert(k);
  }
}

TriangleIndex::Key TriangleIndex::key(std::int64_t x, std::int64_t y, std::int64_t z) const {
  return ((x + kOffset) & kMask) | ((y + kOffset) & kMask) << kBits |
         ((z + kOffset) & kMask) << (2 * kBits);
}

Eigen::Array3i TriangleIndex::cellOf(const Eigen::Vector3d& p) const {
  return (p.array() / options_.cell_m).floor().cast<int>();
}

void TriangleIndex::insert(std::uint32_t k) {
  const Triangle3& t = triangles_[k];
  if (!t.a.allFinite() || !t.b.allFinite() || !t.c.allFinite()) {
    throw std::invalid_argument("TriangleIndex: a corner is not finite");
  }
  const Eigen::Array3i lo = cellOf(t.a.cwiseMin(t.b).cwiseMin(t.c));
  const Eigen::Array3i hi = cellOf(t.a.cwiseMax(t.b).cwiseMax(t.c));
  lo_ = k == 0 ? lo : lo_.min(lo);
  hi_ = k == 0 ? hi : hi_.max(hi);
  for (int x = lo.x(); x <= hi.x(); ++x) {
    for (int y = lo.y(); y <= hi.y(); ++y) {
      for (int z = lo.z(); z <= hi.z(); ++z) {
        cells_[key(x, y, z)].push_back(k);
      }
    }
  }
}

double TriangleIndex::scanCell(const Eigen::Array3i& c, const Eigen::Vector3d& p,
                               double best) const {
  const auto it = cells_.find(key(c.x(), c.y(), c.z()));
  if (it == cells_.end()) {
    return best;
  }
  for (const std::uint32_t k : it->second) {
    best = std::min(best, (closestPointOnTriangle(triangles_[k], p) - p).norm());
  }
  return best;
}

double TriangleIndex::distance(const Eigen::Vector3d& p) const {
  double best = options_.max_distance_m;
  if (triangles_.empty()) {
    return best;
  }
  const Eigen::Array3i c = cellOf(p);
  const int max_ring = static_cast<int>(std::ceil(options_.max_distance_m / options_.cell_m)) + 1;
  // Offsets that stay inside the box of the occupied cells (a far query,
  // such as a map surface across solid space, would otherwise look up
  // thousands of empty cells above and below the building).
  const Eigen::Array3i from = lo_ - c, to = hi_ - c;
  for (int r = 0; r <= max_ring; ++r) {
    // Cells of shell r (Chebyshev distance r from c) inside that box.
    const int z0 = std::max(-r, from.z()), z1 = std::min(r, to.z());
    for (int dx = std::max(-r, from.x()); dx <= std::min(r, to.x()); ++dx) {
      for (int dy = std::max(-r, from.y()); dy <= std::min(r, to.y()); ++dy) {
        if (std::abs(dx) == r || std::abs(dy) == r) {
          for (int dz = z0; dz <= z1; ++dz) {
            best = scanCell(c + Eigen::Array3i(dx, dy, dz), p, best);
          }
        } else {
          for (const int dz : {-r, r}) {  // the shell's top and bottom (r > 0 here)
            if (dz >= z0 && dz <= z1) {
              best = scanCell(c + Eigen::Array3i(dx, dy, dz), p, best);
            }
          }
        }
      }
    }
    // Every cell of a later shell is at least r cells away.
    if (best <= r * options_.cell_m) {
      break;
    }
  }
  return best;
}

}  // namespace pmap::eval
