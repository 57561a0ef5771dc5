#include "pmap/em/online_mstep.h"

#include <algorithm>
#include <cmath>

#include "pmap/em/model_selection.h"
#include "pmap/em/selection_policy.h"

namespace pmap::em {

OnlineMStep::OnlineMStep(const PlanarEmOptions& em, const OnlineEmOptions& online,
                         OnlineStore& store)
    : options_(em),
      online_(online),
      store_(store),
      model_(em.sigma_m, em.z_max_m),
      index_(model_.cutoffDistance(em.responsibility_tolerance)),
      rng_(em.seed) {}

int OnlineMStep::aliveCount() const {
  return static_cast<int>(std::count_if(surfaces_.begin(), surfaces_.end(),
                                        [](const OnlineSurface& s) { return s.alive; }));
}

Cause OnlineMStep::evaluate(std::size_t i) const {
  std::vector<std::int32_t>& cand = candidates_;
  index_.candidates(store_.point(i), cand);
  Cause c;
  c.best_score = model_.outlierScore();
  double second = -1e300;
  for (const std::int32_t j : cand) {
    const double s = score(i, surfaces_[static_cast<std::size_t>(j)].rect);
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

// Beyond the paper: a measurement just past the end of a surface (the robot
// drives 8 cm between scans, more than the 7.2 cm outlier distance at
// sigma 2 cm) continues the surface of an adjacent measurement when it lies
// on that surface's plane, so walls grow with the robot instead of being
// re-seeded piece by piece and fused afterwards.
std::int32_t OnlineMStep::continuation(std::size_t i) const {
  const double within = growDistance(options_);
  for (const std::int32_t n : store_.neighbours()[i]) {
    if (n < 0) {
      continue;
    }
    const std::int32_t j = store_.best(static_cast<std::size_t>(n));
    if (j >= 0 && std::abs(surfaces_[static_cast<std::size_t>(j)].rect.planeDistance(
                      store_.point(i))) <= within) {
      return j;
    }
  }
  return -1;
}

int OnlineMStep::maximizeActive() {
  int n = 0;
  for (std::size_t j = 0; j < surfaces_.size(); ++j) {
    if (surfaces_[j].alive && store_.surface(static_cast<std::int32_t>(j)).active) {
      maximize(static_cast<std::int32_t>(j));
      ++n;
    }
  }
  return n;
}

std::vector<std::int32_t> OnlineMStep::sampleMembers(std::int32_t j, int cap) {
  const std::vector<std::int32_t>& members = store_.surface(j).members;
  if (members.size() <= static_cast<std::size_t>(cap)) {
    return members;
  }
  std::vector<std::int32_t> out;
  std::uniform_int_distribution<std::size_t> pick(0, members.size() - 1);
  for (int k = 0; k < cap; ++k) {
    out.push_back(members[pick(rng_)]);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::vector<std::int32_t> OnlineMStep::rectangleBasis(std::int32_t j) {
  std::vector<std::int32_t> basis = sampleMembers(j, online_.sample_cap);
  const auto sampled = static_cast<std::ptrdiff_t>(basis.size());
  // A sample comes sorted; all members of a small surface do not.
  if (!std::is_sorted(basis.begin(), basis.end())) {
    std::sort(basis.begin(), basis.end());
  }
  for (const auto* list :
       {&surfaces_[static_cast<std::size_t>(j)].hull, &store_.surface(j).fresh}) {
    for (const std::int32_t i : *list) {
      if (store_.best(static_cast<std::size_t>(i)) == j) {
        basis.push_back(i);
      }
    }
  }
  // Only the few hull and fresh points need sorting, then one merge.
  std::sort(basis.begin() + sampled, basis.end());
  std::inplace_merge(basis.begin(), basis.begin() + sampled, basis.end());
  basis.erase(std::unique(basis.begin(), basis.end()), basis.end());
  return basis;
}

// Online M-step of one surface: plane from the exact hard-assignment
// moments (eqs. 24-27), rectangle (eq. 29) from the previous hull, the new
// members and a capped random subsample.
void OnlineMStep::maximize(std::int32_t j) {
  Membership& m = store_.surface(j);
  OnlineSurface& s = surfaces_[static_cast<std::size_t>(j)];
  m.active = false;
  Rectangle fitted = s.rect;
  if (m.members.size() < 3 ||
      planeFromMoments(m.moments, fitted.normal, fitted) != FitStatus::kOk) {
    m.fresh.clear();
    return;
  }
  const std::vector<std::int32_t> coherent = coherentMembers(
      rectangleBasis(j), store_.neighbours(), store_.bests(), options_.rules.coherent_neighbours);
  std::vector<std::int32_t> hull;
  if (fitRectangleWithHull(store_.points(), coherent, fitted, hull) == FitStatus::kOk) {
    s.rect = fitted;
    s.hull = std::move(hull);
    index_.update(j, s.rect);
    // A rectangle its points cover poorly (a ceiling continued around a
    // corner into an L) is cut at once, before it spreads further.
    s.poorly_covered = coverageJudged(s.rect.area(), coherent.size(), options_) &&
                       poorlyCovered(emptyArea(store_.points(), coherent, s.rect,
                                               coverageCell(s.rect.area(), coherent.size())),
                                     s.rect.area(), options_);
  }
  m.fresh.clear();
}

std::int32_t OnlineMStep::create(const Rectangle& rect, const std::vector<std::int32_t>& members,
                                 int scan) {
  OnlineSurface s;
  s.rect = rect;
  s.id = next_id_++;
  s.created_scan = scan;
  const std::int32_t j = store_.addSurface(rect.centre);
  surfaces_.push_back(std::move(s));
  index_.update(j, rect);
  for (const std::int32_t i : members) {
    store_.assign(static_cast<std::size_t>(i), j);
  }
  return j;
}

void OnlineMStep::remove(std::int32_t j) {
  const std::vector<std::int32_t> members = store_.surface(j).members;
  for (const std::int32_t i : members) {
    store_.assign(static_cast<std::size_t>(i), -1);
    store_.resetVisits(static_cast<std::size_t>(i));  // its points get a fresh look
    store_.enqueue(static_cast<std::size_t>(i));
  }
  OnlineSurface& s = surfaces_[static_cast<std::size_t>(j)];
  s.alive = false;
  s.hull.clear();
  store_.surface(j).members.clear();
  store_.surface(j).fresh.clear();
  index_.remove(j);
}

void OnlineMStep::reshape(std::int32_t j, const Rectangle& rect) {
  surfaces_[static_cast<std::size_t>(j)].rect = rect;
  index_.update(j, rect);
}

}  // namespace pmap::em
