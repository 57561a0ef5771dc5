#include "pmap/em/online_em.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <stdexcept>

namespace pmap::em {

OnlineEm::OnlineEm(const PlanarEmOptions& em, const OnlineEmOptions& online)
    : options_(em),
      online_(online),
      store_(online.seed_window_scans),
      mstep_(em, online, store_),
      selection_(em, online, store_, mstep_) {
  assert(em.validate(nullptr) && online.validate(nullptr));
}

// One E-step visit: re-derive the most likely cause; keep the point in the
// revisit queue while it is unexplained or on a boundary and not frozen.
void OnlineEm::revisit(std::size_t i, OnlineUpdate& u) {
  Cause c = mstep_.evaluate(i);
  if (c.best < 0) {
    c.best = mstep_.continuation(i);
  }
  if (c.best != store_.best(i)) {
    store_.assign(i, c.best);
    ++u.reassigned;
  }
  const bool doubtful = c.best < 0 || c.margin < online_.boundary_margin_nats;
  if (doubtful && store_.visits(i) < online_.freeze_after) {
    store_.enqueue(i);
  }
}

void OnlineEm::revisitQueued(std::size_t budget, OnlineUpdate& u) {
  for (std::size_t k = 0; k < budget; ++k) {
    const std::size_t i = store_.popQueued();
    ++u.revisited;
    revisit(i, u);
  }
}

OnlineUpdate OnlineEm::addScan(const std::vector<Eigen::Vector3d>& points,
                               const std::vector<GridKey>& keys) {
  OnlineUpdate u;
  // E-step over the bounded set: the new scan, then queued past points (the
  // oldest first; the new scan's doubtful points join the queue's end).
  const std::size_t queued_before = store_.queueSize();
  const std::size_t first = store_.appendScan(points, keys);
  ++scans_;
  u.new_points = static_cast<int>(points.size());
  for (std::size_t i = first; i < store_.size(); ++i) {
    revisit(i, u);
  }
  revisitQueued(std::min(queued_before, static_cast<std::size_t>(online_.revisit_budget)), u);
  // Model selection, then the M-step of the active surfaces.
  u.changes = selection_.select(scans_);
  u.active_surfaces = mstep_.maximizeActive();
  // One structural change per scan: a poorly covered surface waits for the
  // next scan when the selection turn changed the model in this one.
  if (u.changes.fused + u.changes.split == 0) {
    u.changes.split += selection_.cutPoorlyCovered(scans_);
  }
  return u;
}

OnlineUpdate OnlineEm::movePoints(const std::vector<std::int32_t>& indices,
                                  const std::vector<Eigen::Vector3d>& new_positions) {
  if (indices.size() != new_positions.size()) {
    throw std::invalid_argument("movePoints: " + std::to_string(indices.size()) + " indices but " +
                                std::to_string(new_positions.size()) + " positions");
  }
  for (std::size_t k = 0; k < indices.size(); ++k) {
    const std::int32_t i = indices[k];
    if (i < 0 || static_cast<std::size_t>(i) >= store_.size()) {
      throw std::invalid_argument("movePoints: index " + std::to_string(i) + " not in [0, " +
                                  std::to_string(store_.size()) + ")");
    }
    if (!new_positions[k].allFinite()) {
      throw std::invalid_argument("movePoints: position " + std::to_string(k) + " is not finite");
    }
  }
  OnlineUpdate u;
  std::vector<std::int32_t> touched;
  for (std::size_t k = 0; k < indices.size(); ++k) {
    const auto i = static_cast<std::size_t>(indices[k]);
    if (store_.best(i) >= 0) {
      touched.push_back(store_.best(i));
    }
    store_.move(i, new_positions[k]);
    store_.resetVisits(i);  // a fresh look at its new place
    store_.enqueue(i);
    ++u.moved;
  }
  std::sort(touched.begin(), touched.end());
  touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
  u.active_surfaces = mstep_.maximizeActive();  // refit the surfaces that moved
  for (const std::int32_t j : touched) {
    selection_.prioritise(j);
  }
  revisitQueued(std::min(store_.queueSize(), static_cast<std::size_t>(online_.revisit_budget)), u);
  u.active_surfaces += mstep_.maximizeActive();
  return u;
}

PlanarMap OnlineEm::map() const {
  PlanarMap m;
  std::vector<std::int32_t> slot_to_index(mstep_.slots(), -1);
  for (std::size_t slot = 0; slot < mstep_.slots(); ++slot) {
    const auto j = static_cast<std::int32_t>(slot);
    const OnlineSurface& s = mstep_.surface(j);
    if (s.alive) {
      slot_to_index[slot] = static_cast<std::int32_t>(m.surfaces.size());
      m.surfaces.push_back(
          {s.rect, s.id, static_cast<std::int32_t>(store_.surface(j).members.size()), s.trimmed});
    }
  }
  const std::size_t n = store_.size();
  m.assignment.resize(n);
  std::size_t explained = 0;
  std::vector<char> outlier(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const std::int32_t b = store_.best(i);
    m.assignment[i] = b >= 0 ? slot_to_index[static_cast<std::size_t>(b)] : -1;
    explained += m.assignment[i] >= 0 ? 1 : 0;
    outlier[i] = m.assignment[i] < 0 ? 1 : 0;
  }
  m.explained_fraction = n == 0 ? 0.0 : static_cast<double>(explained) / static_cast<double>(n);
  m.fine_triangles = fineTriangles(store_.points(), store_.neighbours(), outlier,
                                   options_.fine_max_edge_m, options_.fine_cell_m);
  return m;
}

OnlineResult OnlineEm::result() const {
  OnlineResult r;
  r.map = map();
  r.scans = scans_;
  r.points = store_.size();
  r.message = "online over " + std::to_string(scans_) + " scans, " +
              std::to_string(r.map.surfaces.size()) + " surfaces";
  return r;
}

}  // namespace pmap::em
