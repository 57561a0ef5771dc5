#include "pmap/poses/free_space.h"

#include <algorithm>
#include <cmath>

namespace pmap::poses {
namespace {

bool inRange(const Rays& s, const Eigen::Vector2d& e) {
  return (e - s.origin).norm() <= FreeSpace::kMaxRangeM;
}

// A scan's surface: its end points, and the line between neighbouring ones
// closer than max_gap unless that line runs along the beams (within 15
// degrees: a depth jump at an edge, not a surface).
std::vector<Eigen::Vector2d> surface(const Rays& s, double max_gap, double step) {
  std::vector<Eigen::Vector2d> out;
  const double cos_shadow = std::cos(15.0 * M_PI / 180.0);
  for (std::size_t i = 0; i < s.ends.size(); ++i) {
    out.push_back(s.ends[i]);
    if (i + 1 == s.ends.size()) {
      break;
    }
    const Eigen::Vector2d d = s.ends[i + 1] - s.ends[i];
    const Eigen::Vector2d beam = (s.ends[i] - s.origin).normalized();
    const double gap = d.norm();
    if (gap < max_gap && std::abs(beam.dot(d)) < cos_shadow * gap) {
      const int n = static_cast<int>(gap / step);
      for (int k = 1; k < n; ++k) {
        out.push_back(s.ends[i] + d * (static_cast<double>(k) / n));
      }
    }
  }
  return out;
}

}  // namespace

FreeSpace::FreeSpace(const std::vector<Rays>& scans, double cell_m, double margin_m,
                     double max_gap_m)
    : cell_m_(cell_m), margin_m_(margin_m) {
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(1e300), hi = -lo;
  for (const Rays& s : scans) {
    lo = lo.cwiseMin(s.origin);
    hi = hi.cwiseMax(s.origin);
    for (const Eigen::Vector2d& e : s.ends) {
      if (inRange(s, e)) {
        lo = lo.cwiseMin(e);
        hi = hi.cwiseMax(e);
      }
    }
  }
  if (scans.empty()) {
    return;
  }
  lo_ = lo - Eigen::Vector2d::Constant(2.0 * cell_m_);
  cols_ = static_cast<int>(std::ceil((hi.x() - lo_.x()) / cell_m_)) + 3;
  rows_ = static_cast<int>(std::ceil((hi.y() - lo_.y()) / cell_m_)) + 3;
  cells_.assign(static_cast<std::size_t>(cols_) * rows_, kUnknown);
  for (const Rays& s : scans) {
    for (const Eigen::Vector2d& e : s.ends) {
      const Eigen::Vector2d d = e - s.origin;
      const double length = std::min(d.norm(), kMaxRangeM) - margin_m_;
      for (double t = 0.0; t < length; t += 0.5 * cell_m_) {  // every cell crossed
        mark(s.origin + t * d.normalized(), kFree);
      }
    }
  }
  // Surfaces and their neighbour cells are never free: a beam grazing a wall
  // passes next to its end points.
  for (const Rays& s : scans) {
    const std::vector<Eigen::Vector2d> seen = surface(s, max_gap_m, 0.5 * cell_m_);
    for (const Eigen::Vector2d& e : seen) {
      if (!inRange(s, e)) {
        continue;
      }
      for (int dc = -1; dc <= 1; ++dc) {
        for (int dr = -1; dr <= 1; ++dr) {
          mark(e + cell_m_ * Eigen::Vector2d(dc, dr), kNearSurface);
        }
      }
    }
    for (const Eigen::Vector2d& e : seen) {
      if (inRange(s, e)) {
        mark(e, kSurface);
      }
    }
  }
}

FreeSpace::Cell FreeSpace::at(const Eigen::Vector2d& p) const {
  const int c = static_cast<int>(std::floor((p.x() - lo_.x()) / cell_m_));
  const int r = static_cast<int>(std::floor((p.y() - lo_.y()) / cell_m_));
  if (c < 0 || r < 0 || c >= cols_ || r >= rows_) {
    return kUnknown;
  }
  return cells_[static_cast<std::size_t>(r) * cols_ + c];
}

void FreeSpace::mark(const Eigen::Vector2d& p, Cell value) {
  const int c = static_cast<int>(std::floor((p.x() - lo_.x()) / cell_m_));
  const int r = static_cast<int>(std::floor((p.y() - lo_.y()) / cell_m_));
  if (c < 0 || r < 0 || c >= cols_ || r >= rows_) {
    return;
  }
  Cell& cell = cells_[static_cast<std::size_t>(r) * cols_ + c];
  cell = std::max(cell, value);  // surface over near-surface over free
}

double FreeSpace::conflict(const std::vector<Eigen::Vector2d>& points) const {
  if (points.empty()) {
    return 0.0;
  }
  const auto in_free =
      std::count_if(points.begin(), points.end(), [&](const auto& p) { return at(p) == kFree; });
  return static_cast<double>(in_free) / static_cast<double>(points.size());
}

double FreeSpace::sameSide(const std::vector<Rays>& scans) const {
  std::size_t on_surface = 0, through_free = 0;
  for (const Rays& s : scans) {
    for (const Eigen::Vector2d& e : s.ends) {
      if (at(e) != kSurface) {
        continue;
      }
      ++on_surface;
      const Eigen::Vector2d before = e - (margin_m_ + 2.0 * cell_m_) * (e - s.origin).normalized();
      through_free += at(before) == kFree ? 1 : 0;
    }
  }
  return on_surface == 0 ? 1.0
                         : static_cast<double>(through_free) / static_cast<double>(on_surface);
}

std::vector<Rays> moved(const std::vector<Rays>& scans, const Pose2& pose) {
  const double c = std::cos(pose.theta), s = std::sin(pose.theta);
  const auto move = [&](const Eigen::Vector2d& q) {
    return Eigen::Vector2d(c * q.x() - s * q.y() + pose.x, s * q.x() + c * q.y() + pose.y);
  };
  std::vector<Rays> out;
  out.reserve(scans.size());
  for (const Rays& r : scans) {
    Rays m{move(r.origin), {}};
    m.ends.reserve(r.ends.size());
    for (const Eigen::Vector2d& q : r.ends) {
      m.ends.push_back(move(q));
    }
    out.push_back(std::move(m));
  }
  return out;
}

std::vector<Eigen::Vector2d> allEnds(const std::vector<Rays>& scans) {
  std::vector<Eigen::Vector2d> out;
  for (const Rays& r : scans) {
    out.insert(out.end(), r.ends.begin(), r.ends.end());
  }
  return out;
}

std::vector<Eigen::Vector2d> densified(const std::vector<Eigen::Vector2d>& points, double max_gap,
                                       double step) {
  std::vector<Eigen::Vector2d> out;
  out.reserve(points.size() * 2);
  for (std::size_t i = 0; i < points.size(); ++i) {
    out.push_back(points[i]);
    if (i + 1 == points.size()) {
      break;
    }
    const Eigen::Vector2d d = points[i + 1] - points[i];
    const double gap = d.norm();
    if (gap < max_gap) {
      const int n = static_cast<int>(gap / step);
      for (int k = 1; k < n; ++k) {
        out.push_back(points[i] + d * (static_cast<double>(k) / n));
      }
    }
  }
  return out;
}

}  // namespace pmap::poses
