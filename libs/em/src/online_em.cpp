#include "pmap/em/online_em.h"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "pmap/em/min_area_rectangle.h"
#include "pmap/em/model_selector.h"

namespace pmap::em {
namespace {

// Indices (into `members`) of the convex hull of their 2D projections.
std::vector<std::int32_t> hullOf(const std::vector<Eigen::Vector3d>& points,
                                 const std::vector<std::int32_t>& members, const Rectangle& rect) {
  std::vector<std::pair<Eigen::Vector2d, std::int32_t>> uv;
  const Eigen::Vector3d v = rect.axisV();
  for (const std::int32_t i : members) {
    const Eigen::Vector3d d = points[static_cast<std::size_t>(i)] - rect.centre;
    uv.push_back({{rect.axis_u.dot(d), v.dot(d)}, i});
  }
  std::vector<Eigen::Vector2d> flat;
  for (const auto& e : uv) {
    flat.push_back(e.first);
  }
  const std::vector<Eigen::Vector2d> hull = convexHull(flat);
  std::vector<std::int32_t> out;
  for (const Eigen::Vector2d& h : hull) {
    for (const auto& e : uv) {
      if (e.first == h) {
        out.push_back(e.second);
        break;
      }
    }
  }
  return out;
}

}  // namespace

OnlineEm::OnlineEm(const PlanarEmOptions& em, const OnlineEmOptions& online)
    : options_(em),
      online_(online),
      model_(em.sigma_m, em.z_max_m),
      cutoff_(model_.cutoffDistance(em.responsibility_tolerance)),
      index_(cutoff_),
      rng_(em.seed) {
  assert(em.validate(nullptr) && online.validate(nullptr));
}

int OnlineEm::surfaceCount() const {
  return static_cast<int>(std::count_if(surfaces_.begin(), surfaces_.end(),
                                        [](const OnlineSurface& s) { return s.alive; }));
}

void OnlineEm::appendScan(const std::vector<Eigen::Vector3d>& points,
                          const std::vector<GridKey>& keys) {
  const std::size_t first = points_.size();
  for (std::size_t k = 0; k < points.size(); ++k) {
    const auto i = static_cast<std::int32_t>(points_.size());
    const GridKey& g = keys[k];
    points_.push_back(points[k]);
    rows_.push_back(g.row);
    best_.push_back(-1);
    member_pos_.push_back(-1);
    visits_.push_back(0);
    queued_.push_back(0);
    not_planar_.push_back(0);
    index_of_key_.emplace(g, i);
    neighbours_.push_back({-1, -1, -1, -1});
    // Link with the neighbours already present (previous beam, next beam,
    // previous scan); the next scan links itself when it comes.
    const GridKey nb[3] = {
        {g.group, g.row, g.col - 1}, {g.group, g.row, g.col + 1}, {g.group, g.row - 1, g.col}};
    const int slot_here[3] = {0, 1, 2};
    const int slot_there[3] = {1, 0, 3};
    for (int s = 0; s < 3; ++s) {
      const auto it = index_of_key_.find(nb[s]);
      if (it != index_of_key_.end() && it->second != i) {
        neighbours_[static_cast<std::size_t>(i)][static_cast<std::size_t>(slot_here[s])] =
            it->second;
        neighbours_[static_cast<std::size_t>(it->second)][static_cast<std::size_t>(slot_there[s])] =
            i;
      }
    }
  }
  window_.emplace_back(first, points.size());
  while (window_.size() > static_cast<std::size_t>(online_.seed_window_scans)) {
    window_.pop_front();
  }
}

OnlineEm::Cause OnlineEm::evaluate(std::size_t i) const {
  std::vector<std::int32_t> cand;
  index_.candidates(points_[i], cand);
  Cause c;
  c.best_score = model_.outlierScore();
  double second = -1e300;
  for (const std::int32_t j : cand) {
    const double s = model_.surfaceScore(
        surfaces_[static_cast<std::size_t>(j)].rect.squaredDistance(points_[i]));
    if (s > c.best_score) {
      second = c.best_score;
      c.best_score = s;
      c.best = j;
    } else if (s > second) {
      second = s;
    }
  }
  if (c.best < 0) {
    second = std::max(second, model_.outlierScore());
  }
  c.margin = c.best_score - second;
  return c;
}

void OnlineEm::assign(std::size_t i, std::int32_t j) {
  const std::int32_t old = best_[i];
  if (old == j) {
    return;
  }
  if (old >= 0) {
    OnlineSurface& s = surfaces_[static_cast<std::size_t>(old)];
    s.moments.add(points_[i], -1.0);
    const std::int32_t pos = member_pos_[i];
    const std::int32_t last = s.members.back();
    s.members[static_cast<std::size_t>(pos)] = last;
    member_pos_[static_cast<std::size_t>(last)] = pos;
    s.members.pop_back();
    s.active = true;
  }
  best_[i] = j;
  member_pos_[i] = -1;
  if (j >= 0) {
    OnlineSurface& s = surfaces_[static_cast<std::size_t>(j)];
    s.moments.add(points_[i], 1.0);
    member_pos_[i] = static_cast<std::int32_t>(s.members.size());
    s.members.push_back(static_cast<std::int32_t>(i));
    s.fresh.push_back(static_cast<std::int32_t>(i));
    s.active = true;
  }
}

// One E-step visit: re-derive the most likely cause; keep the point in the
// revisit queue while it is unexplained or on a boundary and not frozen.
void OnlineEm::revisit(std::size_t i, OnlineUpdate& u) {
  const Cause c = evaluate(i);
  if (c.best != best_[i]) {
    assign(i, c.best);
    ++u.reassigned;
  }
  const bool doubtful = c.best < 0 || c.margin < online_.boundary_margin_nats;
  if (doubtful && visits_[i] < online_.freeze_after && !queued_[i]) {
    queued_[i] = 1;
    queue_.push_back(static_cast<std::int32_t>(i));
  }
}

std::vector<std::int32_t> OnlineEm::sampleMembers(const OnlineSurface& s, int cap) {
  if (s.members.size() <= static_cast<std::size_t>(cap)) {
    return s.members;
  }
  std::vector<std::int32_t> out;
  std::uniform_int_distribution<std::size_t> pick(0, s.members.size() - 1);
  for (int k = 0; k < cap; ++k) {
    out.push_back(s.members[pick(rng_)]);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

// Online M-step of one surface: plane from the exact hard-assignment
// moments (eqs. 24-27), rectangle (eq. 29) from the previous hull, the new
// members and a capped random subsample.
void OnlineEm::maximize(std::int32_t j) {
  OnlineSurface& s = surfaces_[static_cast<std::size_t>(j)];
  s.active = false;
  if (s.members.size() < 3) {
    s.fresh.clear();
    return;
  }
  Rectangle fitted = s.rect;
  if (planeFromMoments(s.moments, fitted.normal, fitted) != FitStatus::kOk) {
    s.fresh.clear();
    return;
  }
  std::vector<std::int32_t> basis = sampleMembers(s, online_.sample_cap);
  for (const std::int32_t i : s.hull) {
    if (best_[static_cast<std::size_t>(i)] == j) {
      basis.push_back(i);
    }
  }
  for (const std::int32_t i : s.fresh) {
    if (best_[static_cast<std::size_t>(i)] == j) {
      basis.push_back(i);
    }
  }
  std::sort(basis.begin(), basis.end());
  basis.erase(std::unique(basis.begin(), basis.end()), basis.end());
  const std::vector<std::int32_t> coherent = coherentMembers(basis, neighbours_, best_, 2);
  if (fitRectangle(points_, coherent, fitted) == FitStatus::kOk) {
    s.rect = fitted;
    s.hull = hullOf(points_, coherent, fitted);
    index_.update(j, s.rect);
  }
  s.fresh.clear();
}

std::int32_t OnlineEm::createSurface(const Rectangle& rect,
                                     const std::vector<std::int32_t>& members) {
  OnlineSurface s;
  s.rect = rect;
  s.id = next_id_++;
  s.created_scan = scans_;
  s.moments.reference = rect.centre;
  const auto j = static_cast<std::int32_t>(surfaces_.size());
  surfaces_.push_back(std::move(s));
  index_.update(j, rect);
  for (const std::int32_t i : members) {
    assign(static_cast<std::size_t>(i), j);
  }
  return j;
}

void OnlineEm::removeSurface(std::int32_t j) {
  OnlineSurface& s = surfaces_[static_cast<std::size_t>(j)];
  const std::vector<std::int32_t> members = s.members;
  for (const std::int32_t i : members) {
    assign(static_cast<std::size_t>(i), -1);
    visits_[static_cast<std::size_t>(i)] = 0;  // its points get a fresh look
    if (!queued_[static_cast<std::size_t>(i)]) {
      queued_[static_cast<std::size_t>(i)] = 1;
      queue_.push_back(i);
    }
  }
  s.alive = false;
  s.members.clear();
  s.hull.clear();
  s.fresh.clear();
  index_.remove(j);
}

OnlineUpdate OnlineEm::addScan(const std::vector<Eigen::Vector3d>& points,
                               const std::vector<GridKey>& keys) {
  OnlineUpdate u;
  const std::size_t first = points_.size();
  appendScan(points, keys);
  ++scans_;
  u.new_points = static_cast<int>(points.size());
  // E-step over the bounded set: the new scan, then queued past points.
  for (std::size_t i = first; i < points_.size(); ++i) {
    revisit(i, u);
  }
  for (int k = 0; k < online_.revisit_budget && !queue_.empty(); ++k) {
    const auto i = static_cast<std::size_t>(queue_.front());
    queue_.pop_front();
    queued_[i] = 0;
    if (i >= first) {
      continue;  // a new point already visited in this scan
    }
    ++visits_[i];
    ++u.revisited;
    revisit(i, u);
  }
  // Model selection, then the M-step of the active surfaces.
  u.changes.added = seedNew();
  u.changes.removed = removeUnsupported();
  selectRoundRobin(u.changes);
  for (std::size_t j = 0; j < surfaces_.size(); ++j) {
    if (surfaces_[j].alive && surfaces_[j].active) {
      maximize(static_cast<std::int32_t>(j));
      ++u.active_surfaces;
    }
  }
  return u;
}

PlanarMap OnlineEm::map() const {
  PlanarMap m;
  std::vector<std::int32_t> slot_to_index(surfaces_.size(), -1);
  for (std::size_t j = 0; j < surfaces_.size(); ++j) {
    if (surfaces_[j].alive) {
      slot_to_index[j] = static_cast<std::int32_t>(m.surfaces.size());
      m.surfaces.push_back({surfaces_[j].rect, surfaces_[j].id,
                            static_cast<std::int32_t>(surfaces_[j].members.size()),
                            surfaces_[j].trimmed});
    }
  }
  m.assignment.resize(points_.size());
  std::size_t explained = 0;
  std::vector<char> outlier(points_.size(), 0);
  for (std::size_t i = 0; i < points_.size(); ++i) {
    const std::int32_t b = best_[i];
    m.assignment[i] = b >= 0 ? slot_to_index[static_cast<std::size_t>(b)] : -1;
    explained += m.assignment[i] >= 0 ? 1 : 0;
    outlier[i] = m.assignment[i] < 0 ? 1 : 0;
  }
  m.explained_fraction =
      points_.empty() ? 0.0 : static_cast<double>(explained) / static_cast<double>(points_.size());
  m.fine_triangles = fineTriangles(points_, neighbours_, outlier, options_.fine_max_edge_m);
  return m;
}

}  // namespace pmap::em
