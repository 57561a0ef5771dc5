#include "pmap/em/online_store.h"

namespace pmap::em {

OnlineStore::OnlineStore(int window_scans, std::size_t reserved) : window_scans_(window_scans) {
  points_.reserve(reserved);
  rows_.reserve(reserved);
  neighbours_.reserve(reserved);
  best_.reserve(reserved);
  member_pos_.reserve(reserved);
  visits_.reserve(reserved);
  queued_.reserve(reserved);
  not_planar_.reserve(reserved);
  seed_tries_.reserve(reserved);
}

std::size_t OnlineStore::appendScan(const std::vector<Eigen::Vector3d>& points,
                                    const std::vector<GridKey>& keys) {
  const std::size_t first = points_.size();
  for (std::size_t k = 0; k < points.size(); ++k) {
    points_.push_back(points[k]);
    rows_.push_back(keys[k].row);
    best_.push_back(-1);
    member_pos_.push_back(-1);
    visits_.push_back(0);
    queued_.push_back(0);
    not_planar_.push_back(0);
    seed_tries_.push_back(0);
    neighbours_.push_back({-1, -1, -1, -1});
  }
  link(keys, first);
  window_.emplace_back(first, points.size());
  while (window_.size() > static_cast<std::size_t>(window_scans_)) {
    window_.pop_front();
  }
  return first;
}

// Keys of this scan, and for the previous row only the last stored row of
// each group: memory and time bounded by the scan, not the map.
void OnlineStore::link(const std::vector<GridKey>& keys, std::size_t first) {
  std::unordered_map<GridKey, std::int32_t, GridKeyHash> here;
  for (std::size_t k = 0; k < keys.size(); ++k) {
    here.emplace(keys[k], static_cast<std::int32_t>(first + k));
  }
  auto connect = [&](std::int32_t i, std::int32_t n, int slot_here, int slot_there) {
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
    connect(i, find({g.group, g.row, g.col - 1}), 0, 1);  // previous beam
    std::int32_t prev = find({g.group, g.row - 1, g.col});
    const auto last = last_row_.find(g.group);
    if (prev < 0 && last != last_row_.end() && last->second.row == g.row - 1) {
      const auto it = last->second.cols.find(g.col);
      prev = it == last->second.cols.end() ? -1 : it->second;
    }
    connect(i, prev, 2, 3);  // same beam, previous scan
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
}

void OnlineStore::move(std::size_t i, const Eigen::Vector3d& p) {
  const std::int32_t j = best_[i];
  if (j >= 0) {
    Membership& s = surfaces_[static_cast<std::size_t>(j)];
    s.moments.add(points_[i], -1.0);
    s.moments.add(p, 1.0);
    s.fresh.push_back(static_cast<std::int32_t>(i));  // its rectangle takes the new place
    s.active = true;
  }
  points_[i] = p;
}

std::int32_t OnlineStore::addSurface(const Eigen::Vector3d& reference) {
  Membership m;
  m.moments.reference = reference;
  surfaces_.push_back(std::move(m));
  return static_cast<std::int32_t>(surfaces_.size() - 1);
}

void OnlineStore::assign(std::size_t i, std::int32_t j) {
  const std::int32_t old = best_[i];
  if (old == j) {
    return;
  }
  if (old >= 0) {
    Membership& s = surfaces_[static_cast<std::size_t>(old)];
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
    Membership& s = surfaces_[static_cast<std::size_t>(j)];
    s.moments.add(points_[i], 1.0);
    member_pos_[i] = static_cast<std::int32_t>(s.members.size());
    s.members.push_back(static_cast<std::int32_t>(i));
    s.fresh.push_back(static_cast<std::int32_t>(i));
    s.active = true;
  }
}

void OnlineStore::enqueue(std::size_t i) {
  if (!queued_[i]) {
    queued_[i] = 1;
    queue_.push_back(static_cast<std::int32_t>(i));
  }
}

std::size_t OnlineStore::popQueued() {
  const auto i = static_cast<std::size_t>(queue_.front());
  queue_.pop_front();
  queued_[i] = 0;
  ++visits_[i];
  return i;
}

}  // namespace pmap::em
