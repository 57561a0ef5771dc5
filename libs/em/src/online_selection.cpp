// Online model selection (section V-C, and beyond it: fusion and splits are
// not limited to a brief window but keep running round robin): seeding,
// removal and the scheduling of the selection turns.
#include "pmap/em/online_selection.h"

#include <algorithm>

#include "pmap/em/model_selection.h"
#include "pmap/em/seeding.h"
#include "pmap/em/selection_policy.h"

namespace pmap::em {

OnlineSelection::OnlineSelection(const PlanarEmOptions& em, const OnlineEmOptions& online,
                                 OnlineStore& store, OnlineMStep& mstep)
    : options_(em), online_(online), store_(store), mstep_(mstep) {}

// The measurements of the last scans as a small cloud of their own. The
// store keeps scans in order, so the window is one contiguous index range.
struct OnlineSelection::SeedWindow {
  std::size_t first = 0;        ///< store index of local point 0
  std::vector<double> outlier;  ///< per local point, 1: may seed
  std::vector<Eigen::Vector3d> points;
  Neighbours neighbours;  ///< in local indices; links out of the window dropped
  std::int32_t toGlobal(std::int32_t local) const {
    return static_cast<std::int32_t>(first) + local;
  }
  std::vector<std::int32_t> toGlobal(const std::vector<std::int32_t>& local) const {
    std::vector<std::int32_t> out;
    out.reserve(local.size());
    for (const std::int32_t l : local) {
      out.push_back(toGlobal(l));
    }
    return out;
  }
};

// Which measurements of the window may seed (points and links come later,
// when there are enough of them: most turns stop here).
OnlineSelection::SeedWindow OnlineSelection::seedWindow() const {
  SeedWindow w;
  const auto& scans = store_.window();
  if (scans.empty()) {
    return w;
  }
  w.first = scans.front().first;
  const std::size_t end = scans.back().first + scans.back().second;
  for (std::size_t i = w.first; i < end; ++i) {
    // A point that stayed unexplained through seed_tries seeding turns is
    // not seeded again (clutter, or a patch too small): bounded work per scan.
    const bool free = store_.best(i) < 0 && !store_.notPlanar(i) &&
                      store_.seedTries(i) < static_cast<std::uint8_t>(online_.seed_tries);
    w.outlier.push_back(free ? 1.0 : 0.0);
  }
  return w;
}

void OnlineSelection::fillWindow(SeedWindow& w) const {
  const std::size_t n = w.outlier.size();
  const auto first = static_cast<std::ptrdiff_t>(w.first);
  w.points.assign(store_.points().begin() + first,
                  store_.points().begin() + first + static_cast<std::ptrdiff_t>(n));
  w.neighbours.assign(n, {-1, -1, -1, -1});
  for (std::size_t k = 0; k < n; ++k) {
    const auto& links = store_.neighbours()[w.first + k];
    for (std::size_t s = 0; s < 4; ++s) {
      const std::int64_t local = static_cast<std::int64_t>(links[s]) - first;
      const bool inside = links[s] >= 0 && local >= 0 && local < static_cast<std::int64_t>(n);
      w.neighbours[k][s] = inside ? static_cast<std::int32_t>(local) : -1;
    }
  }
}

// The validity of a grown region (selection_policy.h); a curved one (a bin)
// marks its points, which are not seeded again.
bool OnlineSelection::acceptSeed(const SeedWindow& w, const std::vector<std::int32_t>& local,
                                 Rectangle& rect) {
  const auto min_points = static_cast<std::size_t>(options_.min_support);
  if (local.size() < min_points || fitSurface(w.points, local, rect) != FitStatus::kOk) {
    return false;
  }
  const std::vector<std::int32_t> g = w.toGlobal(local);
  const SurfaceVerdict verdict = checkSurface(store_.measurements(), g, rect, options_, min_points);
  if (verdict.curved) {
    for (const std::int32_t i : g) {
      store_.markNotPlanar(static_cast<std::size_t>(i));
    }
  }
  return verdict.valid();
}

// New surfaces from the unexplained measurements of the last scans: the
// offline seeding (three adjacent poorly explained points, grown over the
// neighbour graph) on that window, kept when it raises the posterior.
int OnlineSelection::seedNew() {
  SeedWindow w = seedWindow();
  if (std::count(w.outlier.begin(), w.outlier.end(), 1.0) < options_.min_support) {
    return 0;
  }
  fillWindow(w);
  PlanarEmOptions seeding = options_;
  seeding.max_new_per_round = online_.seeds_per_turn;
  const SeedResult s = seedSurfaces(
      w.points, w.neighbours, w.outlier, mstep_.model(), seeding,
      [&](const std::vector<std::int32_t>& local, Rectangle& r) { return acceptSeed(w, local, r); },
      mstep_.rng(), static_cast<std::size_t>(online_.seed_regions_per_turn));
  for (std::size_t k = 0; k < w.outlier.size(); ++k) {
    if (w.outlier[k] > 0.0) {
      store_.countSeedTry(w.first + k);
    }
  }
  int added = 0;
  const double s_star = mstep_.model().outlierScore();
  for (std::size_t k = 0; k < s.surfaces.size(); ++k) {
    const std::vector<std::int32_t> members = w.toGlobal(s.members[k]);
    double loglik = 0.0;  // eq. (30): its members from the outlier class to it
    for (const std::int32_t i : members) {
      loglik += mstep_.score(static_cast<std::size_t>(i), s.surfaces[k]) - s_star;
    }
    const double empty = emptyArea(store_.points(), members, s.surfaces[k], options_.split_cell_m);
    if (raisesPosterior(posteriorGain(loglik, 1, empty, options_), options_)) {
      mstep_.create(s.surfaces[k], members, scan_);
      ++added;
    }
  }
  return added;
}

// Surfaces still below min_support after removal_after_scans scans (a grace
// period: a new surface gathers its points over the next scans), or curved,
// are removed; their points go back to the revisit queue.
int OnlineSelection::removeUnsupported() {
  int removed = 0;
  for (std::size_t slot = 0; slot < mstep_.slots(); ++slot) {
    const auto j = static_cast<std::int32_t>(slot);
    const OnlineSurface& s = mstep_.surface(j);
    if (!s.alive) {
      continue;
    }
    const Membership& m = store_.surface(j);
    const bool old = scan_ - s.created_scan >= online_.removal_after_scans;
    bool drop = old && m.members.size() < static_cast<std::size_t>(options_.min_support);
    if (!drop && m.active) {
      const std::vector<std::int32_t> sample = mstep_.sampleMembers(j, online_.sample_cap);
      if (curvedSurface(store_.measurements(), sample, s.rect, options_)) {
        for (const std::int32_t i : m.members) {
          store_.markNotPlanar(static_cast<std::size_t>(i));
        }
        drop = true;
      }
    }
    if (drop) {
      mstep_.remove(j);
      ++removed;
    }
  }
  return removed;
}

std::int32_t OnlineSelection::nextSurface() {
  const std::size_t n = mstep_.slots();
  std::size_t tries = 0;
  do {
    cursor_ = (cursor_ + 1) % n;
  } while (!mstep_.surface(static_cast<std::int32_t>(cursor_)).alive && ++tries < n);
  return mstep_.surface(static_cast<std::int32_t>(cursor_)).alive
             ? static_cast<std::int32_t>(cursor_)
             : -1;
}

void OnlineSelection::selectTurn(SelectionChanges& c) {
  for (int k = 0; k < online_.selection_per_scan && mstep_.slots() > 0; ++k) {
    // Surfaces whose points moved first: a fusion test (a wall seen twice).
    while (!priority_.empty() && !mstep_.surface(priority_.front()).alive) {
      priority_.pop_front();
    }
    if (!priority_.empty()) {
      const std::int32_t j = priority_.front();
      priority_.pop_front();
      c.fused += tryFuse(j) ? 1 : 0;
      continue;
    }
    const std::int32_t j = nextSurface();
    if (j < 0) {
      return;
    }
    // Fusion and split tests take turns, so that one scan pays for one of them.
    if (fuse_turn_) {
      c.fused += tryFuse(j) ? 1 : 0;
    } else {
      c.split += trySplit(j) ? 1 : 0;
    }
    fuse_turn_ = !fuse_turn_;
  }
}

SelectionChanges OnlineSelection::select(int scan) {
  scan_ = scan;
  SelectionChanges c;
  if (scan % online_.seed_every_scans == 0) {
    c.added = seedNew();
  }
  c.removed = removeUnsupported();
  if ((scan + 1) % online_.select_every_scans == 0) {
    selectTurn(c);
  }
  return c;
}

// A cut that found nothing is tried again only once the surface has gained
// min_support members (enough for a part of its own): the same rectangle
// and nearly the same points give the same verdict, and a surface that stays
// poorly covered would otherwise be tested at every scan it is active
// (cluttered seed 1: 112 tries, 3 cuts, a split test each).
int OnlineSelection::cutPoorlyCovered(int scan) {
  scan_ = scan;
  for (std::size_t slot = 0; slot < mstep_.slots(); ++slot) {
    const auto j = static_cast<std::int32_t>(slot);
    OnlineSurface& s = mstep_.surface(j);
    if (!s.alive || !s.poorly_covered) {
      continue;
    }
    s.poorly_covered = false;
    const std::size_t members = store_.surface(j).members.size();
    if (s.cut_refused_members > 0 &&
        members < s.cut_refused_members + static_cast<std::size_t>(options_.min_support)) {
      continue;
    }
    const bool cut = trySplit(j);  // may add a surface: `s` is not used after it
    mstep_.surface(j).cut_refused_members = cut ? 0 : members;
    return cut ? 1 : 0;  // at most one per scan
  }
  return 0;
}

void OnlineSelection::prioritise(std::int32_t j) {
  if (std::find(priority_.begin(), priority_.end(), j) == priority_.end()) {
    priority_.push_back(j);
  }
}

}  // namespace pmap::em
