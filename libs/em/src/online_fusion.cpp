// Online fusion and the L re-cut: every surface keeps being re-examined
// (round robin) against its coplanar neighbours, on capped subsamples of
// their points and their hulls, with the decisions of selection_policy.h.
#include <algorithm>
#include <iterator>
#include <set>

#include "pmap/em/coverage_cut.h"
#include "pmap/em/model_selection.h"
#include "pmap/em/online_selection.h"
#include "pmap/em/selection_policy.h"

namespace pmap::em {

// Hard-score change (eq. 30's first term) of explaining both subsamples by
// `merged`, each scaled to all members of its surface.
double OnlineSelection::fusionLikelihoodChange(std::int32_t j, std::int32_t k,
                                               const Rectangle& merged,
                                               const std::vector<std::int32_t>& sa,
                                               const std::vector<std::int32_t>& sb) const {
  const double s_star = mstep_.model().outlierScore();
  double change = 0.0;
  for (const std::int32_t part : {j, k}) {
    const std::vector<std::int32_t>& sample = part == j ? sa : sb;
    const Rectangle& rect = mstep_.surface(part).rect;
    double sum = 0.0;
    for (const std::int32_t i : sample) {
      const auto p = static_cast<std::size_t>(i);
      sum += std::max(mstep_.score(p, merged), s_star) - mstep_.score(p, rect);
    }
    change += sample.empty() ? 0.0
                             : sum * static_cast<double>(store_.surface(part).members.size()) /
                                   static_cast<double>(sample.size());
  }
  return change;
}

bool OnlineSelection::tryFuse(std::int32_t j) {
  const OnlineSurface& a = mstep_.surface(j);
  std::set<std::int32_t> partners;
  std::vector<std::int32_t> cand;
  for (const Eigen::Vector3d& c : a.rect.corners()) {
    mstep_.index().candidates(c, cand);
    partners.insert(cand.begin(), cand.end());
  }
  for (const std::int32_t k : partners) {
    const OnlineSurface& b = mstep_.surface(k);
    if (k == j || !b.alive || !fusionPartners(a.rect, b.rect, options_)) {
      continue;
    }
    const int half = online_.selection_sample_cap / 2;
    const std::vector<std::int32_t> sa = mstep_.sampleMembers(j, half);
    const std::vector<std::int32_t> sb = mstep_.sampleMembers(k, half);
    const std::vector<std::int32_t>& ma = store_.surface(j).members;
    const std::vector<std::int32_t>& mb = store_.surface(k).members;
    Rectangle m = ma.size() >= mb.size() ? a.rect : b.rect;
    if (fitSurface(store_.points(), unionOf({sa, sb, a.hull, b.hull}), m) != FitStatus::kOk ||
        curvedSurface(store_.measurements(), unionOf({sa, sb}), m, options_)) {
      continue;
    }
    const double loglik = fusionLikelihoodChange(j, k, m, sa, sb);
    // The empty-area prior only when the likelihood alone gains (it needs
    // every member: work saved on most pairs).
    bool gains = raisesPosterior(posteriorGain(loglik, -1, 0.0, options_), options_);
    if (gains) {
      const double cell = options_.split_cell_m;
      const double more_empty = emptyArea(store_.points(), unionOf({ma, mb}), m, cell) -
                                emptyArea(store_.points(), ma, a.rect, cell) -
                                emptyArea(store_.points(), mb, b.rect, cell);
      gains = raisesPosterior(posteriorGain(loglik, -1, more_empty, options_), options_);
    }
    if (!gains) {  // kept apart: an L is re-cut instead
      if (tryRecut(j, k)) {
        return true;
      }
      continue;
    }
    fuse(j, k, m);
    return true;
  }
  return false;
}

// Surface j becomes `merged` and takes surface k's members; k is removed.
void OnlineSelection::fuse(std::int32_t j, std::int32_t k, const Rectangle& merged) {
  const std::vector<std::int32_t> moving = store_.surface(k).members;
  const std::vector<std::int32_t> hull = unionOf({mstep_.surface(j).hull, mstep_.surface(k).hull});
  mstep_.remove(k);
  for (const std::int32_t i : moving) {
    store_.assign(static_cast<std::size_t>(i), j);
  }
  OnlineSurface& a = mstep_.surface(j);
  a.hull = hull;
  a.id = mstep_.newId();
  mstep_.reshape(j, merged);
}

// Two coplanar neighbours that fusion keeps apart (an L: a ceiling around a
// corner) are brought into the canonical form the offline fusion step gives
// them: the larger surface runs through the corner. It takes the other's
// members within its own width at that end (cornerTransfer), when that
// grows it clearly (rules.recut_min_growth_percent: the corner square, not
// a fringe), some stay with the other surface, and the two rectangles
// refitted around their points leave no more empty area than min_gain buys.
bool OnlineSelection::tryRecut(std::int32_t j, std::int32_t k) {
  const bool j_big = store_.surface(j).members.size() >= store_.surface(k).members.size();
  const std::int32_t target = j_big ? j : k;
  const std::int32_t source = j_big ? k : j;
  const std::vector<std::int32_t>& big = store_.surface(target).members;
  const std::vector<std::int32_t>& other = store_.surface(source).members;
  const int cap = online_.selection_sample_cap / 2;
  std::vector<std::int32_t> big_pts;  // a subsample and the hull: the extent
  for (const std::int32_t i :
       unionOf({mstep_.sampleMembers(target, cap), mstep_.surface(target).hull})) {
    if (store_.best(static_cast<std::size_t>(i)) == target) {
      big_pts.push_back(i);
    }
  }
  const std::vector<std::int32_t> moving =
      cornerTransfer(store_.points(), mstep_.surface(target).rect, big_pts,
                     mstep_.surface(source).rect, other, mstep_.model().sigma(), options_.rules);
  if (!recutGrowsLarger(big.size() + moving.size(), big.size(), options_) ||
      !recutLeavesSmaller(moving.size(), other.size(), options_)) {
    return false;
  }
  std::vector<std::int32_t> staying, others = other;
  std::sort(others.begin(), others.end());
  std::set_difference(others.begin(), others.end(), moving.begin(), moving.end(),
                      std::back_inserter(staying));
  // Rectangles from subsamples plus the moved points and the hulls (the
  // extent), as the online M-step fits them.
  std::vector<std::int32_t> other_pts;
  big_pts.insert(big_pts.end(), moving.begin(), moving.end());
  for (const std::int32_t i :
       unionOf({mstep_.sampleMembers(source, cap), mstep_.surface(source).hull})) {
    if (store_.best(static_cast<std::size_t>(i)) == source &&
        !std::binary_search(moving.begin(), moving.end(), i)) {
      other_pts.push_back(i);
    }
  }
  Rectangle r_big = mstep_.surface(target).rect, r_other = mstep_.surface(source).rect;
  const auto& z = store_.points();
  if (other_pts.size() < 3 || fitRectangle(z, big_pts, r_big) != FitStatus::kOk ||
      fitRectangle(z, other_pts, r_other) != FitStatus::kOk) {
    return false;
  }
  const double cell = options_.split_cell_m;
  const double more_empty = emptyArea(z, unionOf({big, moving}), r_big, cell) +
                            emptyArea(z, staying, r_other, cell) -
                            emptyArea(z, big, mstep_.surface(target).rect, cell) -
                            emptyArea(z, other, mstep_.surface(source).rect, cell);
  if (!recutAffordable(posteriorGain(0.0, 0, more_empty, options_), options_)) {
    return false;
  }
  mstep_.surface(target).id = mstep_.newId();
  mstep_.surface(source).id = mstep_.newId();
  mstep_.reshape(j, j_big ? r_big : r_other);
  mstep_.reshape(k, j_big ? r_other : r_big);
  for (const std::int32_t i : moving) {
    store_.assign(static_cast<std::size_t>(i), target);
  }
  return true;
}

}  // namespace pmap::em
