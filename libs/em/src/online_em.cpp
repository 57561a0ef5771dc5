#include "pmap/em/online_em.h"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "pmap/em/model_selection.h"
#include "pmap/em/model_selector.h"

namespace pmap::em {
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
  // Keys of this scan, and for the previous row only the last stored row of
  // each group: memory and time bounded by the scan, not the map.
  std::unordered_map<GridKey, std::int32_t, GridKeyHash> here;
  for (std::size_t k = 0; k < points.size(); ++k) {
    const auto i = static_cast<std::int32_t>(points_.size());
    points_.push_back(points[k]);
    rows_.push_back(keys[k].row);
    best_.push_back(-1);
    member_pos_.push_back(-1);
    visits_.push_back(0);
    queued_.push_back(0);
    not_planar_.push_back(0);
    seed_tries_.push_back(0);
    neighbours_.push_back({-1, -1, -1, -1});
    here.emplace(keys[k], i);
  }
  auto link = [&](std::int32_t i, std::int32_t n, int slot_here, int slot_there) {
    if (n >= 0 && n != i) {
      neighbours_[static_cast<std::size_t>(i)][static_cast<std::size_t>(slot_here)] = n;
      neighbours_[static_cast<std::size_t>(n)][static_cast<std::size_t>(slot_there)] = i;
    }
  };
  auto find = [&](const GridKey& g) -> std::int32_t {
    const auto it = here.find(g);
    return it == here.end() ? -1 : it->second;
  };
  for (std::size_t k = 0; k < keys.size(); ++k) {
    const GridKey& g = keys[k];
    const auto i = static_cast<std::int32_t>(first + k);
    link(i, find({g.group, g.row, g.col - 1}), 0, 1);  // previous beam
    std::int32_t prev = find({g.group, g.row - 1, g.col});
    const auto last = last_row_.find(g.group);
    if (prev < 0 && last != last_row_.end() && last->second.row == g.row - 1) {
      const auto it = last->second.cols.find(g.col);
      prev = it == last->second.cols.end() ? -1 : it->second;
    }
    link(i, prev, 2, 3);  // same beam, previous scan
  }
  for (std::size_t k = 0; k < keys.size(); ++k) {  // the newest row of each group
    RowIndex& r = last_row_[keys[k].group];
    if (keys[k].row > r.row || r.row == INT32_MIN) {
      r.row = keys[k].row;
      r.cols.clear();
    }
    if (keys[k].row == r.row) {
      r.cols[keys[k].col] = static_cast<std::int32_t>(first + k);
    }
  }
  window_.emplace_back(first, points.size());
  while (window_.size() > static_cast<std::size_t>(online_.seed_window_scans)) {
    window_.pop_front();
  }
}

// Beyond the paper: a measurement just past the end of a surface (the robot
// drives 8 cm between scans, more than the 7.2 cm outlier distance at
// sigma 2 cm) continues the surface of an adjacent measurement when it lies
// on that surface's plane (within 2.5 sigma), so walls grow with the robot
// instead of being re-seeded piece by piece and fused afterwards.
std::int32_t OnlineEm::continuation(std::size_t i) const {
  for (const std::int32_t n : neighbours_[i]) {
    if (n < 0) {
      continue;
    }
    const std::int32_t j = best_[static_cast<std::size_t>(n)];
    if (j >= 0 && std::abs(surfaces_[static_cast<std::size_t>(j)].rect.planeDistance(points_[i])) <=
                      2.5 * model_.sigma()) {
      return j;
    }
  }
  return -1;
}

// Whether `basis` (a subsample spread over the surface) leaves most of the
// rectangle empty, on cells sized for ~4 sampled points each.
bool OnlineEm::poorCoverage(const std::vector<std::int32_t>& basis, const Rectangle& rect) const {
  if (rect.area() < 4.0 || basis.size() < 32) {
    return false;
  }
  const double cell = 2.0 * std::sqrt(rect.area() / static_cast<double>(basis.size()));
  const double empty = emptyArea(points_, basis, rect, cell);
  return empty > 0.5 * rect.area();
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
  Cause c = evaluate(i);
  if (c.best < 0) {
    c.best = continuation(i);
  }
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
  std::vector<std::int32_t> hull;
  if (fitRectangleWithHull(points_, coherent, fitted, hull) == FitStatus::kOk) {
    s.rect = fitted;
    s.hull = std::move(hull);
    index_.update(j, s.rect);
    // A rectangle its points cover poorly (a ceiling continued around a
    // corner into an L) is cut at once, before it spreads further.
    s.poorly_covered = poorCoverage(coherent, s.rect);
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
  // E-step over the bounded set: the new scan, then queued past points (the
  // oldest first; the new scan's doubtful points join the queue's end).
  const std::size_t queued_before = queue_.size();
  for (std::size_t i = first; i < points_.size(); ++i) {
    revisit(i, u);
  }
  const std::size_t budget =
      std::min(queued_before, static_cast<std::size_t>(online_.revisit_budget));
  for (std::size_t k = 0; k < budget; ++k) {
    const auto i = static_cast<std::size_t>(queue_.front());
    queue_.pop_front();
    queued_[i] = 0;
    ++visits_[i];
    ++u.revisited;
    revisit(i, u);
  }
  // Model selection, then the M-step of the active surfaces.
  if (scans_ % online_.seed_every_scans == 0) {
    u.changes.added = seedNew();
  }
  u.changes.removed = removeUnsupported();
  if ((scans_ + 1) % online_.select_every_scans == 0) {
    selectRoundRobin(u.changes);
  }
  for (std::size_t j = 0; j < surfaces_.size(); ++j) {
    if (surfaces_[j].alive && surfaces_[j].active) {
      maximize(static_cast<std::int32_t>(j));
      ++u.active_surfaces;
    }
  }
  for (std::size_t j = 0; j < surfaces_.size(); ++j) {
    if (surfaces_[j].alive && surfaces_[j].poorly_covered) {
      surfaces_[j].poorly_covered = false;
      if (trySplit(static_cast<std::int32_t>(j))) {
        ++u.changes.split;
      }
      break;  // at most one per scan
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
