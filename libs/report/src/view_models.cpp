#include "view_models.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace pmap::report::detail {
namespace {

constexpr double kSteepNz = 0.7;
/// Wall tops are drawn darker than the walls: light walls on the white
/// background would hardly show.
constexpr double kFootprintShade = 0.6;

Eigen::Vector3d centre(const products::TexturedQuad& q) {
  return 0.25 * (q.corners[0] + q.corners[1] + q.corners[2] + q.corners[3]);
}

/// RGB in [0, 1] the rectangle shows: its colour or its texture's mean.
Eigen::Vector3d shownColor(const products::TexturedQuad& q) {
  if (q.texture.empty()) {
    return q.color;
  }
  const cv::Scalar bgr = cv::mean(q.texture);
  if (q.texture.channels() == 1) {
    return Eigen::Vector3d::Constant(bgr[0] / 255.0);
  }
  return Eigen::Vector3d(bgr[2], bgr[1], bgr[0]) / 255.0;
}

/// Appends a horizontal strip around the segment a-b at height z to the
/// fine triangles (which have per-vertex colours by then).
void addStrip(products::ColoredTriangles& fine, const Eigen::Vector2d& a, const Eigen::Vector2d& b,
              double z, double width_m, const Eigen::Vector3d& rgb) {
  Eigen::Vector2d d = b - a;
  d = d.norm() > 1e-9 ? d.normalized() : Eigen::Vector2d::UnitX();
  const Eigen::Vector2d side = 0.5 * width_m * Eigen::Vector2d(-d.y(), d.x());
  const Eigen::Vector2d a0 = a - 0.5 * width_m * d, b0 = b + 0.5 * width_m * d;
  const auto first = static_cast<std::uint32_t>(fine.vertices.size());
  const std::array<Eigen::Vector2d, 4> corners{a0 - side, b0 - side, b0 + side, a0 + side};
  for (const Eigen::Vector2d& p : corners) {
    fine.vertices.emplace_back(p.x(), p.y(), z);
    fine.colors.push_back(rgb.cast<float>());
  }
  fine.triangles.push_back({first, first + 1, first + 2});
  fine.triangles.push_back({first, first + 2, first + 3});
}

/// Gives every fine vertex its own colour (the uniform one where none).
void ensureVertexColors(products::ColoredTriangles& fine) {
  if (fine.colors.size() != fine.vertices.size()) {
    fine.colors.assign(fine.vertices.size(), fine.color.cast<float>());
  }
}

/// The two corners farthest apart horizontally (the rectangle's footprint).
std::pair<Eigen::Vector2d, Eigen::Vector2d> footprint(const products::TexturedQuad& q) {
  std::pair<Eigen::Vector2d, Eigen::Vector2d> best{q.corners[0].head<2>(), q.corners[0].head<2>()};
  double longest = -1;
  for (std::size_t i = 0; i < 4; ++i) {
    for (std::size_t j = i + 1; j < 4; ++j) {
      const double len = (q.corners[i].head<2>() - q.corners[j].head<2>()).norm();
      if (len > longest) {
        longest = len;
        best = {q.corners[i].head<2>(), q.corners[j].head<2>()};
      }
    }
  }
  return best;
}

double topZ(const products::TexturedQuad& q) {
  double z = q.corners[0].z();
  for (const auto& c : q.corners) {
    z = std::max(z, c.z());
  }
  return z;
}

}  // namespace

products::MapModel withoutCeilings(const products::MapModel& model, double floor_z, double cut_m) {
  const double cut_z = floor_z + cut_m;
  products::MapModel out;
  out.path = model.path;
  for (const auto& q : model.quads) {
    if (!(std::abs(q.normal.z()) > kSteepNz && centre(q).z() > cut_z)) {
      out.quads.push_back(q);
    }
  }
  out.fine.vertices = model.fine.vertices;
  out.fine.colors = model.fine.colors;
  out.fine.color = model.fine.color;
  for (const auto& t : model.fine.triangles) {
    const bool valid = std::all_of(t.begin(), t.end(),
                                   [&](std::uint32_t i) { return i < model.fine.vertices.size(); });
    if (!valid) {
      out.fine.triangles.push_back(t);  // left for buildMapScene to report
      continue;
    }
    const double z = (model.fine.vertices[t[0]].z() + model.fine.vertices[t[1]].z() +
                      model.fine.vertices[t[2]].z()) /
                     3.0;
    if (z <= cut_z) {
      out.fine.triangles.push_back(t);
    }
  }
  return out;
}

void addFootprints(products::MapModel& model, double width_m, const Eigen::Vector3d& path_rgb) {
  ensureVertexColors(model.fine);
  for (const auto& q : model.quads) {
    if (std::abs(q.normal.z()) <= kSteepNz) {
      const auto [a, b] = footprint(q);
      addStrip(model.fine, a, b, topZ(q), width_m, kFootprintShade * shownColor(q));
    }
  }
  const Eigen::Vector3d* from = nullptr;
  for (const Eigen::Vector3d& p : model.path) {
    if (!p.allFinite()) {
      continue;
    }
    if (from == nullptr) {
      from = &p;
    } else if ((p - *from).head<2>().norm() >= width_m || &p == &model.path.back()) {
      addStrip(model.fine, from->head<2>(), p.head<2>(), std::max(from->z(), p.z()) + 0.1, width_m,
               path_rgb);
      from = &p;
    }
  }
  model.path.clear();
}

}  // namespace pmap::report::detail
