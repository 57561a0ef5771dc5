#include "pmap/em/surface_fit.h"

#include <Eigen/Eigenvalues>
#include <cmath>

#include "pmap/em/min_area_rectangle.h"
#include "pmap/em/parallel.h"

namespace pmap::em {

void PlaneMoments::add(const Eigen::Vector3d& p, double w) {
  const Eigen::Vector3d d = p - reference;  // centred: no cancellation far from the origin
  weight += w;
  sum += w * d;
  sum_sq.noalias() += w * d * d.transpose();
}

void PlaneMoments::merge(const PlaneMoments& o) {
  weight += o.weight;
  sum += o.sum;
  sum_sq += o.sum_sq;
}

FitStatus planeFromMoments(const PlaneMoments& m, const Eigen::Vector3d& previous_normal,
                           Rectangle& rect) {
  if (!(m.weight > 1e-9)) {
    return FitStatus::kTooFewPoints;
  }
  const Eigen::Vector3d mean = m.sum / m.weight;  // eq. (24), relative to the reference
  const Eigen::Matrix3d scatter = m.sum_sq - m.weight * mean * mean.transpose();  // A_j
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(scatter);  // eigenvalues ascending
  const Eigen::Vector3d lambda = eig.eigenvalues();
  // A plane needs two clearly spread directions; a line or a point is degenerate.
  if (!(lambda(1) > 1e-6 * lambda(2)) || !(lambda(2) > 0.0)) {
    return FitStatus::kDegenerate;
  }
  Eigen::Vector3d normal = eig.eigenvectors().col(0);  // eq. (27): smallest eigenvalue
  if (normal.dot(previous_normal) < 0.0) {
    normal = -normal;
  }
  rect.normal = normal.normalized();
  rect.centre = m.reference + mean;
  rect.offset = rect.normal.dot(rect.centre);  // eq. (25): beta = alpha . z-bar
  rect.reproject();
  return FitStatus::kOk;
}

FitStatus fitRectangle(const std::vector<Eigen::Vector3d>& points,
                       const std::vector<std::int32_t>& members, Rectangle& rect) {
  if (members.size() < 3) {
    return FitStatus::kTooFewPoints;
  }
  const Eigen::Vector3d u = rect.axis_u;
  const Eigen::Vector3d v = rect.axisV();
  std::vector<Eigen::Vector2d> uv;
  uv.reserve(members.size());
  for (const std::int32_t i : members) {
    const Eigen::Vector3d d = points[i] - rect.centre;
    uv.emplace_back(u.dot(d), v.dot(d));
  }
  const Rect2D r = minAreaRectangle(uv);
  rect.centre += u * r.centre.x() + v * r.centre.y();
  rect.axis_u = (u * r.axis.x() + v * r.axis.y()).normalized();
  rect.half_u = r.half_a;
  rect.half_v = r.half_b;
  rect.reproject();
  return FitStatus::kOk;
}

FitStatus fitRectangleWithHull(const std::vector<Eigen::Vector3d>& points,
                               const std::vector<std::int32_t>& members, Rectangle& rect,
                               std::vector<std::int32_t>& hull) {
  hull.clear();
  if (members.size() < 3) {
    return FitStatus::kTooFewPoints;
  }
  const Eigen::Vector3d u = rect.axis_u;
  const Eigen::Vector3d v = rect.axisV();
  std::vector<Eigen::Vector2d> uv;
  uv.reserve(members.size());
  for (const std::int32_t i : members) {
    const Eigen::Vector3d d = points[static_cast<std::size_t>(i)] - rect.centre;
    uv.emplace_back(u.dot(d), v.dot(d));
  }
  std::vector<Eigen::Vector2d> hull_uv;
  for (const std::size_t k : convexHullIndices(uv)) {
    hull.push_back(members[k]);
    hull_uv.push_back(uv[k]);
  }
  const Rect2D r = hull_uv.size() >= 3 ? minAreaRectangleOfHull(hull_uv) : minAreaRectangle(uv);
  rect.centre += u * r.centre.x() + v * r.centre.y();
  rect.axis_u = (u * r.axis.x() + v * r.axis.y()).normalized();
  rect.half_u = r.half_a;
  rect.half_v = r.half_b;
  rect.reproject();
  return FitStatus::kOk;
}

FitStatus fitSurface(const std::vector<Eigen::Vector3d>& points,
                     const std::vector<std::int32_t>& members, Rectangle& rect) {
  if (members.size() < 3) {
    return FitStatus::kTooFewPoints;
  }
  PlaneMoments m;
  m.reference = points[members.front()];
  for (const std::int32_t i : members) {
    m.add(points[i], 1.0);
  }
  const FitStatus plane = planeFromMoments(m, rect.normal, rect);
  if (plane != FitStatus::kOk) {
    return plane;
  }
  return fitRectangle(points, members, rect);
}

std::vector<std::vector<std::int32_t>> hardMembers(const Responsibilities& resp,
                                                   std::size_t surfaces) {
  std::vector<std::vector<std::int32_t>> members(surfaces);
  for (std::size_t i = 0; i < resp.best.size(); ++i) {
    if (resp.best[i] >= 0) {
      members[static_cast<std::size_t>(resp.best[i])].push_back(static_cast<std::int32_t>(i));
    }
  }
  return members;
}

std::vector<std::int32_t> coherentMembers(const std::vector<std::int32_t>& members,
                                          const Neighbours& neighbours,
                                          const std::vector<std::int32_t>& best, int min_same) {
  std::vector<std::int32_t> out;
  out.reserve(members.size());
  for (const std::int32_t i : members) {
    int same = 0;
    for (const std::int32_t n : neighbours[static_cast<std::size_t>(i)]) {
      same += (n >= 0 && best[static_cast<std::size_t>(n)] == best[static_cast<std::size_t>(i)]);
    }
    if (same >= min_same) {
      out.push_back(i);
    }
  }
  return out.size() >= 3 ? out : members;
}

void maximizeSurfaces(const std::vector<Eigen::Vector3d>& points, const Neighbours& neighbours,
                      const Responsibilities& resp, int threads, std::vector<Surface>& surfaces,
                      int coherent_neighbours) {
  const std::size_t n = points.size();
  const std::size_t J = surfaces.size();
  std::vector<std::vector<PlaneMoments>> partial(chunkCount(n), std::vector<PlaneMoments>(J));
  forEachChunk(n, threads, [&](std::size_t c, std::size_t begin, std::size_t end) {
    auto& acc = partial[c];
    for (std::size_t j = 0; j < J; ++j) {
      acc[j].reference = surfaces[j].rect.centre;
    }
    for (std::size_t i = begin; i < end; ++i) {
      for (std::uint32_t k = resp.offsets[i]; k < resp.offsets[i + 1]; ++k) {
        acc[static_cast<std::size_t>(resp.surface[k])].add(points[i], resp.weight[k]);
      }
    }
  });
  const auto members = hardMembers(resp, J);
  for (std::size_t j = 0; j < J; ++j) {
    PlaneMoments m;
    m.reference = surfaces[j].rect.centre;
    for (const auto& acc : partial) {
      m.merge(acc[j]);
    }
    Rectangle fitted = surfaces[j].rect;
    surfaces[j].support = static_cast<std::int32_t>(members[j].size());
    if (planeFromMoments(m, fitted.normal, fitted) != FitStatus::kOk) {
      continue;
    }
    if (fitted.bounded &&
        fitRectangle(points,
                     coherentMembers(members[j], neighbours, resp.best, coherent_neighbours),
                     fitted) != FitStatus::kOk) {
      continue;
    }
    surfaces[j].rect = fitted;
  }
}

}  // namespace pmap::em
