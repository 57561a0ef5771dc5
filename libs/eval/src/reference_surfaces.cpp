#include "pmap/eval/reference_surfaces.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <limits>

namespace pmap::eval {
namespace {

/// A rectangle's own 2D frame: p = origin + a * eu + b * ev, 0 <= a <= lu,
/// 0 <= b <= lv inside.
struct RectangleFrame {
  explicit RectangleFrame(const Rectangle& r) : origin(r[0]) {
    const Eigen::Vector3d u = r[1] - r[0];
    const Eigen::Vector3d v = r[3] - r[0];
    lu = u.norm();
    eu = lu > 0 ? Eigen::Vector3d(u / lu) : Eigen::Vector3d::UnitX();
    const Eigen::Vector3d v_perp = v - eu * eu.dot(v);
    lv = v_perp.norm();
    ev = lv > 0 ? Eigen::Vector3d(v_perp / lv) : eu.unitOrthogonal();
  }
  Eigen::Vector2d coords(const Eigen::Vector3d& p) const {
    const Eigen::Vector3d d = p - origin;
    return {d.dot(eu), d.dot(ev)};
  }
  Eigen::Vector3d point(double a, double b) const { return origin + a * eu + b * ev; }

  Eigen::Vector3d origin;
  Eigen::Vector3d eu;
  Eigen::Vector3d ev;
  double lu = 0;
  double lv = 0;
};

/// Running bounding box of projected points.
struct Extent {
  Eigen::Vector2d min = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector2d max = -min;
  std::size_t points = 0;
  void add(const Eigen::Vector2d& q) {
    min = min.cwiseMin(q);
    max = max.cwiseMax(q);
    ++points;
  }
};

Rectangle clip(const Rectangle& rect, const RectangleFrame& f, const Extent& e) {
  if (e.points == 0) {
    return rect;
  }
  const double a0 = std::clamp(e.min.x(), 0.0, f.lu);
  const double a1 = std::clamp(e.max.x(), 0.0, f.lu);
  const double b0 = std::clamp(e.min.y(), 0.0, f.lv);
  const double b1 = std::clamp(e.max.y(), 0.0, f.lv);
  return {f.point(a0, b0), f.point(a1, b0), f.point(a1, b1), f.point(a0, b1)};
}

}  // namespace

Rectangle clipToPoints(const Rectangle& rect, const std::vector<Eigen::Vector3d>& points) {
  const RectangleFrame frame(rect);
  Extent extent;
  for (const auto& p : points) {
    extent.add(frame.coords(p));
  }
  return clip(rect, frame, extent);
}

std::vector<ReferenceSurface> referenceSurfaces(const GroundTruth& gt,
                                                const std::unordered_map<int, std::size_t>& hits,
                                                const std::vector<Eigen::Vector3d>& points,
                                                const std::vector<int>& labels,
                                                std::size_t min_hits) {
  std::vector<ReferenceSurface> refs;
  std::unordered_map<int, std::size_t> index;  // surface id -> position in refs
  for (const auto& s : gt.surfaces) {
    const auto it = hits.find(s.id);
    if (it != hits.end() && it->second >= min_hits && !gt.isClutter(s.id)) {
      refs.push_back({s, it->second, 0, s.corners});
    }
  }
  std::sort(refs.begin(), refs.end(),
            [](const auto& a, const auto& b) { return a.rect.id < b.rect.id; });
  std::vector<RectangleFrame> frames;
  std::vector<Extent> extents(refs.size());
  for (std::size_t k = 0; k < refs.size(); ++k) {
    index[refs[k].rect.id] = k;
    frames.emplace_back(refs[k].rect.corners);
  }
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto it = index.find(labels[i]);
    if (it != index.end()) {
      extents[it->second].add(frames[it->second].coords(points[i]));
    }
  }
  for (std::size_t k = 0; k < refs.size(); ++k) {
    refs[k].points = extents[k].points;
    refs[k].clipped = clip(refs[k].rect.corners, frames[k], extents[k]);
  }
  return refs;
}

}  // namespace pmap::eval
