// Online fusion and splits: every surface keeps being re-examined (round
// robin), on a capped subsample of its points, so a door first absorbed by
// its wall is split off by later data and its early points change surface.
#include <algorithm>
#include <cmath>
#include <iterator>
#include <set>

#include "pmap/em/coverage_cut.h"
#include "pmap/em/model_selection.h"
#include "pmap/em/online_em.h"
#include "pmap/em/planarity.h"
#include "pmap/em/split_proposals.h"

namespace pmap::em {
namespace {

double rectangleGap(const Rectangle& a, const Rectangle& b) {
  double gap2 = std::min(a.squaredDistance(b.centre), b.squaredDistance(a.centre));
  for (const auto& c : a.corners()) {
    gap2 = std::min(gap2, b.squaredDistance(c));
  }
  for (const auto& c : b.corners()) {
    gap2 = std::min(gap2, a.squaredDistance(c));
  }
  return std::sqrt(gap2);
}

std::vector<std::int32_t> merged(std::vector<std::int32_t> a, const std::vector<std::int32_t>& b) {
  a.insert(a.end(), b.begin(), b.end());
  std::sort(a.begin(), a.end());
  a.erase(std::unique(a.begin(), a.end()), a.end());
  return a;
}

}  // namespace

bool OnlineEm::tryFuse(std::int32_t j) {
  OnlineSurface& a = surfaces_[static_cast<std::size_t>(j)];
  std::set<std::int32_t> partners;
  std::vector<std::int32_t> cand;
  for (const Eigen::Vector3d& c : a.rect.corners()) {
    index_.candidates(c, cand);
    partners.insert(cand.begin(), cand.end());
  }
  const double cos_max = std::cos(options_.fuse_angle_deg * M_PI / 180.0);
  for (const std::int32_t k : partners) {
    OnlineSurface& b = surfaces_[static_cast<std::size_t>(k)];
    if (k == j || !b.alive || std::abs(a.rect.normal.dot(b.rect.normal)) < cos_max ||
        std::abs(a.rect.planeDistance(b.rect.centre)) > options_.fuse_offset_m ||
        std::abs(b.rect.planeDistance(a.rect.centre)) > options_.fuse_offset_m ||
        rectangleGap(a.rect, b.rect) > options_.fuse_gap_m + options_.fuse_offset_m) {
      continue;
    }
    const int half = online_.selection_sample_cap / 2;
    const std::vector<std::int32_t> sa = sampleMembers(a, half);
    const std::vector<std::int32_t> sb = sampleMembers(b, half);
    Rectangle m = a.members.size() >= b.members.size() ? a.rect : b.rect;
    if (fitSurface(points_, merged(merged(merged(sa, sb), a.hull), b.hull), m) != FitStatus::kOk ||
        isCurved(measurePlanarity(points_, merged(sa, sb), m), options_.min_curvature_radius_m)) {
      continue;
    }
    // Hard-score change on the subsamples, scaled to all members.
    double gain = options_.kappa;
    for (const auto* part : {&a, &b}) {
      const std::vector<std::int32_t>& sample = part == &a ? sa : sb;
      double sum = 0.0;
      for (const std::int32_t i : sample) {
        const Eigen::Vector3d& p = points_[static_cast<std::size_t>(i)];
        sum += std::max(model_.surfaceScore(m.squaredDistance(p)), model_.outlierScore()) -
               model_.surfaceScore(part->rect.squaredDistance(p));
      }
      gain += sample.empty() ? 0.0
                             : sum * static_cast<double>(part->members.size()) /
                                   static_cast<double>(sample.size());
    }
    if (gain > options_.min_gain) {  // then with the empty-area prior
      const double cell = options_.split_cell_m;
      gain +=
          options_.empty_area_cost * (emptyArea(points_, a.members, a.rect, cell) +
                                      emptyArea(points_, b.members, b.rect, cell) -
                                      emptyArea(points_, merged(a.members, b.members), m, cell));
    }
    if (gain <= options_.min_gain) {  // kept apart: an L is re-cut instead
      if (tryRecut(j, k)) {
        return true;
      }
      continue;
    }
    const std::vector<std::int32_t> moving = b.members;
    const std::vector<std::int32_t> hull = merged(a.hull, b.hull);
    a.rect = m;
    removeSurface(k);
    for (const std::int32_t i : moving) {
      assign(static_cast<std::size_t>(i), j);
    }
    a.hull = hull;
    a.id = next_id_++;
    index_.update(j, a.rect);
    return true;
  }
  return false;
}

// Two coplanar neighbours that fusion keeps apart (an L: a ceiling around a
// corner) are brought into the canonical form the offline fusion step gives
// them: the larger surface runs through the corner. It takes the other's
// members within its own width at that end (cornerTransfer), when they are
// clearly many (5 % of its own members: the corner square, not a fringe),
// some stay with the other surface, and the two rectangles refitted around
// their points leave no more empty area.
bool OnlineEm::tryRecut(std::int32_t j, std::int32_t k) {
  OnlineSurface& a = surfaces_[static_cast<std::size_t>(j)];
  OnlineSurface& b = surfaces_[static_cast<std::size_t>(k)];
  OnlineSurface& big = a.members.size() >= b.members.size() ? a : b;
  OnlineSurface& other = &big == &a ? b : a;
  const auto target = static_cast<std::int32_t>(&big == &a ? j : k);
  const auto source = static_cast<std::int32_t>(&big == &a ? k : j);
  const int cap = online_.selection_sample_cap / 2;
  std::vector<std::int32_t> big_pts;  // a subsample and the hull: the extent
  for (const std::int32_t i : merged(sampleMembers(big, cap), big.hull)) {
    if (best_[static_cast<std::size_t>(i)] == target) {
      big_pts.push_back(i);
    }
  }
  std::vector<std::int32_t> moving =
      cornerTransfer(points_, big.rect, big_pts, other.rect, other.members, model_.sigma());
  if (moving.size() * 20 < big.members.size() || moving.size() * 10 > other.members.size() * 9) {
    return false;
  }
  std::vector<std::int32_t> staying, others = other.members;
  std::sort(others.begin(), others.end());
  std::set_difference(others.begin(), others.end(), moving.begin(), moving.end(),
                      std::back_inserter(staying));
  // Rectangles from subsamples plus the moved points and the hulls (the
  // extent), as the online M-step fits them.
  std::vector<std::int32_t> other_pts;
  big_pts.insert(big_pts.end(), moving.begin(), moving.end());
  for (const std::int32_t i : merged(sampleMembers(other, cap), other.hull)) {
    if (best_[static_cast<std::size_t>(i)] == source &&
        !std::binary_search(moving.begin(), moving.end(), i)) {
      other_pts.push_back(i);
    }
  }
  Rectangle r_big = big.rect, r_other = other.rect;
  if (other_pts.size() < 3 || fitRectangle(points_, big_pts, r_big) != FitStatus::kOk ||
      fitRectangle(points_, other_pts, r_other) != FitStatus::kOk) {
    return false;
  }
  const double cell = options_.split_cell_m;
  const double before = emptyArea(points_, big.members, big.rect, cell) +
                        emptyArea(points_, other.members, other.rect, cell);
  const double after = emptyArea(points_, merged(big.members, moving), r_big, cell) +
                       emptyArea(points_, staying, r_other, cell);
  if (after > before + options_.min_gain / options_.empty_area_cost) {
    return false;
  }
  big.rect = r_big;
  other.rect = r_other;
  big.id = next_id_++;
  other.id = next_id_++;
  index_.update(j, a.rect);
  index_.update(k, b.rect);
  for (const std::int32_t i : moving) {
    assign(static_cast<std::size_t>(i), target);
  }
  return true;
}

// Whether some member of surface j would be explained neither by `kept` (j's
// rectangle after a trim) nor by another surface better than by the outlier
// class.
bool OnlineEm::leavesUnexplained(std::int32_t j, const Rectangle& kept) const {
  const double s_star = model_.outlierScore();
  std::vector<std::int32_t> cand;
  for (const std::int32_t i : surfaces_[static_cast<std::size_t>(j)].members) {
    const Eigen::Vector3d& p = points_[static_cast<std::size_t>(i)];
    if (model_.surfaceScore(kept.squaredDistance(p)) > s_star) {
      continue;
    }
    index_.candidates(p, cand);
    const bool elsewhere = std::any_of(cand.begin(), cand.end(), [&](std::int32_t k) {
      return k != j && model_.surfaceScore(
                           surfaces_[static_cast<std::size_t>(k)].rect.squaredDistance(p)) > s_star;
    });
    if (!elsewhere) {
      return true;
    }
  }
  return false;
}

// A capped subsample of surface j for its split tests, with how much worse
// each sampled point is explained without the surface.
OnlineEm::SplitSample OnlineEm::splitSample(std::int32_t j) {
  const OnlineSurface& s = surfaces_[static_cast<std::size_t>(j)];
  SplitSample x;
  x.points = merged(sampleMembers(s, online_.selection_sample_cap), s.hull);
  x.scale = static_cast<double>(s.members.size()) / static_cast<double>(x.points.size());
  x.min_part =
      static_cast<std::size_t>(std::max(8.0, static_cast<double>(options_.min_support) / x.scale));
  // Cells coarse enough that a subsample still covers a fully seen surface.
  x.cell = std::max(options_.split_cell_m,
                    1.5 * std::sqrt(s.rect.area() / static_cast<double>(x.points.size())));
  std::vector<std::int32_t> cand;
  for (const std::int32_t i : x.points) {
    const Eigen::Vector3d& p = points_[static_cast<std::size_t>(i)];
    index_.candidates(p, cand);
    double other = model_.outlierScore();
    for (const std::int32_t k : cand) {
      if (k != j) {
        other = std::max(
            other,
            model_.surfaceScore(surfaces_[static_cast<std::size_t>(k)].rect.squaredDistance(p)));
      }
    }
    x.loss.push_back(std::max(0.0, model_.surfaceScore(s.rect.squaredDistance(p)) - other) *
                     x.scale);
  }
  return x;
}

// The candidate replacements of surface j: residual splits (two parts) and
// the best coverage cut (two parts, or one kept: a trim).
std::vector<std::vector<std::vector<std::int32_t>>> OnlineEm::splitOptions(
    std::int32_t j, const SplitSample& x) const {
  const OnlineSurface& s = surfaces_[static_cast<std::size_t>(j)];
  std::vector<std::vector<std::vector<std::int32_t>>> options;
  for (const SplitProposal& p :
       residualSplits(points_, x.points, s.rect, x.cell, options_.split_min_offset_m,
                      model_.sigma(), x.min_part)) {
    options.push_back({p.part_a, p.part_b});
  }
  auto c = coverageCut(points_, x.points, x.loss, s.rect, x.cell, options_.empty_area_cost,
                       options_.kappa, x.min_part, true);
  // A surface is trimmed of points it leaves unexplained at most once: the
  // outlier band would let it win them back, regrow and re-trim it forever.
  // Handing points over to the surfaces that explain them can be repeated.
  if (c && c->keep != CutKeep::kBoth && s.trimmed) {
    Rectangle kept = s.rect;
    const auto& part = c->keep == CutKeep::kPartA ? c->parts.part_a : c->parts.part_b;
    if (fitSurface(points_, part, kept) != FitStatus::kOk || leavesUnexplained(j, kept)) {
      c = coverageCut(points_, x.points, x.loss, s.rect, x.cell, options_.empty_area_cost,
                      options_.kappa, x.min_part, false);
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

// The log-posterior change (eq. 30, hard scores on the subsample scaled to
// all members, kappa, the empty-area prior) of replacing surface j by `rects`
// fitted to `parts`.
double OnlineEm::splitGain(std::int32_t j, const SplitSample& x,
                           const std::vector<std::vector<std::int32_t>>& parts,
                           const std::vector<Rectangle>& rects) const {
  const Rectangle& old = surfaces_[static_cast<std::size_t>(j)].rect;
  double gain = -options_.kappa * static_cast<double>(rects.size() - 1) +
                options_.empty_area_cost * emptyArea(points_, x.points, old, x.cell);
  for (std::size_t k = 0; k < rects.size(); ++k) {
    gain -= options_.empty_area_cost * emptyArea(points_, parts[k], rects[k], x.cell);
  }
  for (std::size_t n = 0; n < x.points.size(); ++n) {
    const Eigen::Vector3d& p = points_[static_cast<std::size_t>(x.points[n])];
    const double was = model_.surfaceScore(old.squaredDistance(p));
    double now = was - x.loss[n] / x.scale;
    for (const Rectangle& r : rects) {
      now = std::max(now, model_.surfaceScore(r.squaredDistance(p)));
    }
    gain += (now - was) * x.scale;
  }
  return gain;
}

bool OnlineEm::trySplit(std::int32_t j) {
  OnlineSurface& s = surfaces_[static_cast<std::size_t>(j)];
  if (s.members.size() < 2 * static_cast<std::size_t>(options_.min_support)) {
    return false;
  }
  const SplitSample x = splitSample(j);
  // The option that raises the posterior most (by more than min_gain).
  double best_gain = options_.min_gain;
  std::vector<Rectangle> best;
  for (const auto& parts : splitOptions(j, x)) {
    std::vector<Rectangle> rects;
    for (const auto& part : parts) {
      Rectangle r = s.rect;
      if (fitSurface(points_, part, r) != FitStatus::kOk ||
          isCurved(measurePlanarity(points_, part, r), options_.min_curvature_radius_m)) {
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
  // Apply: the surface becomes the first part; every member is re-derived.
  const std::vector<std::int32_t> members = s.members;
  s.rect = best[0];
  s.trimmed = s.trimmed || best.size() == 1;
  s.id = next_id_++;
  // The hull is kept: its points that stay members still bound the next
  // M-step's rectangle (a capped random subsample alone would shrink it
  // where the surface is sparsely seen, e.g. a ceiling's corner).
  index_.update(j, s.rect);
  if (best.size() > 1) {
    createSurface(best[1], {});
  }
  for (const std::int32_t i : members) {
    assign(static_cast<std::size_t>(i), evaluate(static_cast<std::size_t>(i)).best);
  }
  return true;
}

}  // namespace pmap::em
