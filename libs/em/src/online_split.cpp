// Online splits: every surface keeps being re-examined (round robin), on a
// capped subsample of its points, so a door first absorbed by its wall is
// split off by later data and its early points change surface. The
// proposals are the offline ones (residual patches, coverage cuts) and the
// decision is eq. (30)'s (selection_policy.h), on the subsample scaled to
// all members.
#include <algorithm>
#include <cmath>

#include "pmap/em/coverage_cut.h"
#include "pmap/em/model_selection.h"
#include "pmap/em/online_selection.h"
#include "pmap/em/selection_policy.h"
#include "pmap/em/split_proposals.h"
#include "pmap/em/surface_fit.h"

namespace pmap::em {

// Whether some member of surface j would be explained neither by `kept` (j's
// rectangle after a trim) nor by another surface better than by the outlier
// class.
bool OnlineSelection::leavesUnexplained(std::int32_t j, const Rectangle& kept) const {
  const double s_star = mstep_.model().outlierScore();
  std::vector<std::int32_t> cand;
  for (const std::int32_t m : store_.surface(j).members) {
    const auto i = static_cast<std::size_t>(m);
    if (mstep_.score(i, kept) > s_star) {
      continue;
    }
    mstep_.index().candidates(store_.point(i), cand);
    const bool elsewhere = std::any_of(cand.begin(), cand.end(), [&](std::int32_t k) {
      return k != j && mstep_.score(i, mstep_.surface(k).rect) > s_star;
    });
    if (!elsewhere) {
      return true;
    }
  }
  return false;
}

// A capped subsample of surface j for its split tests, with how much worse
// each sampled point is explained without the surface.
OnlineSelection::SplitSample OnlineSelection::splitSample(std::int32_t j) {
  const OnlineSurface& s = mstep_.surface(j);
  SplitSample x;
  x.points = unionOf({mstep_.sampleMembers(j, online_.selection_sample_cap), s.hull});
  x.scale =
      static_cast<double>(store_.surface(j).members.size()) / static_cast<double>(x.points.size());
  x.min_part = minSplitPart(x.scale, options_);
  x.cell = sampledSplitCell(s.rect.area(), x.points.size(), options_);
  std::vector<std::int32_t> cand;
  for (const std::int32_t m : x.points) {
    const auto i = static_cast<std::size_t>(m);
    mstep_.index().candidates(store_.point(i), cand);
    double other = mstep_.model().outlierScore();
    for (const std::int32_t k : cand) {
      if (k != j) {
        other = std::max(other, mstep_.score(i, mstep_.surface(k).rect));
      }
    }
    x.loss.push_back(std::max(0.0, mstep_.score(i, s.rect) - other) * x.scale);
  }
  return x;
}

// The candidate replacements of surface j: residual splits (two parts) and
// the best coverage cut (two parts, or one kept: a trim).
std::vector<std::vector<std::vector<std::int32_t>>> OnlineSelection::splitOptions(
    std::int32_t j, const SplitSample& x) const {
  const OnlineSurface& s = mstep_.surface(j);
  const auto& z = store_.points();
  std::vector<std::vector<std::vector<std::int32_t>>> options;
  for (const SplitProposal& p :
       residualSplits(z, x.points, s.rect, x.cell, options_.split_min_offset_m,
                      mstep_.model().sigma(), x.min_part, options_.rules)) {
    options.push_back({p.part_a, p.part_b});
  }
  auto c = coverageCut(z, x.points, x.loss, s.rect, x.cell, options_.empty_area_cost,
                       options_.kappa, x.min_part, true);
  // A surface is trimmed of points it leaves unexplained at most once: the
  // outlier band would let it win them back, regrow and re-trim it forever.
  // Handing points over to the surfaces that explain them can be repeated.
  if (c && c->keep != CutKeep::kBoth && s.trimmed) {
    Rectangle kept = s.rect;
    const auto& part = c->keep == CutKeep::kPartA ? c->parts.part_a : c->parts.part_b;
    if (fitSurface(z, part, kept) != FitStatus::kOk || leavesUnexplained(j, kept)) {
      c = coverageCut(z, x.points, x.loss, s.rect, x.cell, options_.empty_area_cost, options_.kappa,
                      x.min_part, false);
    }
  }
  if (c) {
    if (c->keep == CutKeep::kBoth) {
      options.push_back({c->parts.part_a, c->parts.part_b});
    } else {
      options.push_back({c->keep == CutKeep::kPartA ? c->parts.part_a : c->parts.part_b});
    }
  }
  return options;
}

// The log-posterior change (eq. 30: hard scores on the subsample scaled to
// all members, kappa, the empty-area prior) of replacing surface j by
// `rects` fitted to `parts`.
double OnlineSelection::splitGain(std::int32_t j, const SplitSample& x,
                                  const std::vector<std::vector<std::int32_t>>& parts,
                                  const std::vector<Rectangle>& rects) const {
  const Rectangle& old = mstep_.surface(j).rect;
  const auto& z = store_.points();
  double more_empty = -emptyArea(z, x.points, old, x.cell);
  for (std::size_t k = 0; k < rects.size(); ++k) {
    more_empty += emptyArea(z, parts[k], rects[k], x.cell);
  }
  double loglik = 0.0;
  for (std::size_t n = 0; n < x.points.size(); ++n) {
    const auto i = static_cast<std::size_t>(x.points[n]);
    const double was = mstep_.score(i, old);
    double now = was - x.loss[n] / x.scale;
    for (const Rectangle& r : rects) {
      now = std::max(now, mstep_.score(i, r));
    }
    loglik += (now - was) * x.scale;
  }
  return posteriorGain(loglik, static_cast<int>(rects.size()) - 1, more_empty, options_);
}

bool OnlineSelection::trySplit(std::int32_t j) {
  // Two valid parts need twice the support (trims of smaller surfaces are
  // left to the offline step: work saved per turn).
  if (store_.surface(j).members.size() < 2 * static_cast<std::size_t>(options_.min_support)) {
    return false;
  }
  const SplitSample x = splitSample(j);
  // The option that raises the posterior most (by more than min_gain).
  double best_gain = options_.min_gain;
  std::vector<Rectangle> best;
  for (const auto& parts : splitOptions(j, x)) {
    std::vector<Rectangle> rects;
    for (const auto& part : parts) {
      // A part of a subsample: its support is the proposal's min_part and
      // its worth the gain below; only its shape is tested here (rows are
      // not: a sliver of sampled points may miss rows its members cover).
      Rectangle r = mstep_.surface(j).rect;
      if (fitSurface(store_.points(), part, r) != FitStatus::kOk ||
          curvedSurface(store_.measurements(), part, r, options_)) {
        break;
      }
      rects.push_back(r);
    }
    const double gain = rects.size() == parts.size() ? splitGain(j, x, parts, rects) : -INFINITY;
    if (gain > best_gain) {
      best_gain = gain;
      best = std::move(rects);
    }
  }
  if (best.empty()) {
    return false;
  }
  applySplit(j, best);
  return true;
}

// Surface j becomes the first part, a new surface the second (if any);
// every member of j is re-derived.
void OnlineSelection::applySplit(std::int32_t j, const std::vector<Rectangle>& parts) {
  const std::vector<std::int32_t> members = store_.surface(j).members;
  OnlineSurface& s = mstep_.surface(j);
  s.trimmed = s.trimmed || parts.size() == 1;
  s.id = mstep_.newId();
  // The hull is kept: its points that stay members still bound the next
  // M-step's rectangle (a capped random subsample alone would shrink it
  // where the surface is sparsely seen, e.g. a ceiling's corner).
  mstep_.reshape(j, parts[0]);
  if (parts.size() > 1) {
    mstep_.create(parts[1], {}, scan_);
  }
  for (const std::int32_t i : members) {
    store_.assign(static_cast<std::size_t>(i), mstep_.evaluate(static_cast<std::size_t>(i)).best);
  }
}

}  // namespace pmap::em
