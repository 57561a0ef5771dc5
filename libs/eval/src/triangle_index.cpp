#include "pmap/eval/triangle_index.h"

#include <algorithm>
#include <array>
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

constexpr std::uint32_t kLeafSize = 4;

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
  if (!(max_distance_m > 0.0 && std::isfinite(max_distance_m))) {
    if (why != nullptr)
      *why = "max_distance_m must be > 0";
    return false;
  }
  return true;
}

TriangleIndex::TriangleIndex(std::vector<Triangle3> triangles, const TriangleIndexOptions& options)
    : triangles_(std::move(triangles)), options_(options) {
  std::string why;
  if (!options_.validate(&why)) {
    throw std::invalid_argument("TriangleIndex: " + why);
  }
  boxes_.reserve(triangles_.size());
  for (const Triangle3& t : triangles_) {
    if (!t.a.allFinite() || !t.b.allFinite() || !t.c.allFinite()) {
      throw std::invalid_argument("TriangleIndex: a corner is not finite");
    }
    Eigen::AlignedBox3d box(t.a);
    box.extend(t.b).extend(t.c);
    boxes_.push_back(box);
  }
  order_.resize(triangles_.size());
  for (std::uint32_t k = 0; k < order_.size(); ++k) {
    order_[k] = k;
  }
  if (!triangles_.empty()) {
    nodes_.reserve(2 * triangles_.size() / kLeafSize + 2);
    build(0, static_cast<std::uint32_t>(triangles_.size()));
  }
}

// The node over order_[first, first + count): its box, then (above
// kLeafSize triangles) the two halves split at the median of the boxes'
// centres along the box's longest side.
std::int32_t TriangleIndex::build(std::uint32_t first, std::uint32_t count) {
  const auto id = static_cast<std::int32_t>(nodes_.size());
  nodes_.emplace_back();
  Eigen::AlignedBox3d box = boxes_[order_[first]];
  for (std::uint32_t k = first + 1; k < first + count; ++k) {
    box.extend(boxes_[order_[k]]);
  }
  nodes_[static_cast<std::size_t>(id)].box = box;
  if (count <= kLeafSize) {
    nodes_[static_cast<std::size_t>(id)].first = first;
    nodes_[static_cast<std::size_t>(id)].count = count;
    return id;
  }
  Eigen::Index axis = 0;
  box.sizes().maxCoeff(&axis);
  const std::uint32_t half = count / 2;
  const auto begin = order_.begin() + first;
  std::nth_element(begin, begin + half, begin + count, [&](std::uint32_t a, std::uint32_t b) {
    const double ca = boxes_[a].center()[axis], cb = boxes_[b].center()[axis];
    return ca < cb || (ca == cb && a < b);
  });
  const std::int32_t left = build(first, half);
  const std::int32_t right = build(first + half, count - half);
  nodes_[static_cast<std::size_t>(id)].left = left;
  nodes_[static_cast<std::size_t>(id)].right = right;
  return id;
}

double TriangleIndex::distance(const Eigen::Vector3d& p) const {
  double best = options_.max_distance_m;
  if (nodes_.empty()) {
    return best;
  }
  // Depth-first: at most one pending sibling per level, and the halving
  // split keeps the depth under 33 for any 32-bit triangle count.
  std::array<std::int32_t, 96> stack{};
  std::size_t size = 0;
  stack[size++] = 0;
  while (size > 0) {
    const Node& n = nodes_[static_cast<std::size_t>(stack[--size])];
    // Every triangle in the box is at least this far: nothing to gain (the
    // margin covers rounding, so that the result is the exact minimum).
    if (n.box.squaredExteriorDistance(p) > best * best * (1.0 + 1e-9)) {
      continue;
    }
    if (n.left < 0) {
      for (std::uint32_t k = n.first; k < n.first + n.count; ++k) {
        const Triangle3& t = triangles_[order_[k]];
        best = std::min(best, (closestPointOnTriangle(t, p) - p).norm());
      }
      continue;
    }
    // The nearer child last, so that it is searched first.
    const Node& l = nodes_[static_cast<std::size_t>(n.left)];
    const Node& r = nodes_[static_cast<std::size_t>(n.right)];
    const bool left_nearer = l.box.squaredExteriorDistance(p) <= r.box.squaredExteriorDistance(p);
    stack[size++] = left_nearer ? n.right : n.left;
    stack[size++] = left_nearer ? n.left : n.right;
  }
  return best;
}

}  // namespace pmap::eval
