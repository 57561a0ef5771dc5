#include "pmap/em/model_selector.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "pmap/em/coverage_cut.h"
#include "pmap/em/model_selection.h"
#include "pmap/em/planarity.h"
#include "pmap/em/rectangle_index.h"
#include "pmap/em/seeding.h"
#include "pmap/em/selection_policy.h"
#include "pmap/em/split_proposals.h"
#include "pmap/em/surface_fit.h"

namespace pmap::em {
namespace {

// Points whose E-step entries list surface j.
std::vector<std::vector<std::int32_t>> entryPoints(const Responsibilities& resp, std::size_t J) {
  std::vector<std::vector<std::int32_t>> out(J);
  for (std::size_t i = 0; i < resp.points(); ++i) {
    for (std::uint32_t k = resp.offsets[i]; k < resp.offsets[i + 1]; ++k) {
      out[static_cast<std::size_t>(resp.surface[k])].push_back(static_cast<std::int32_t>(i));
    }
  }
  return out;
}

// Change of the summed point scores if each surface alone were removed: the
// score of each of its points without it minus with it (recomputed from the
// other terms: exact even when the surface explains a point almost alone).
std::vector<double> removalChanges(const Responsibilities& resp, double s_star, std::size_t J,
                                   PlanarEmOptions::Scoring scoring) {
  std::vector<double> change(J, 0.0);
  for (std::size_t i = 0; i < resp.points(); ++i) {
    const double with = pointScore(resp, i, s_star, scoring);
    for (std::uint32_t k = resp.offsets[i]; k < resp.offsets[i + 1]; ++k) {
      change[static_cast<std::size_t>(resp.surface[k])] +=
          pointScore(resp, i, s_star, scoring, k) - with;
    }
  }
  return change;
}

}  // namespace

ModelSelector::ModelSelector(const std::vector<Eigen::Vector3d>& points,
                             const Neighbours& neighbours, const std::vector<std::int32_t>& rows,
                             const PlanarEmOptions& options)
    : points_(points),
      neighbours_(neighbours),
      rows_(rows),
      options_(options),
      model_(options.sigma_m, options.z_max_m),
      cutoff_(model_.cutoffDistance(options.responsibility_tolerance)),
      grid_(points, std::max(0.5, 4.0 * cutoff_)),
      not_planar_(points.size(), 0),
      rng_(options.seed) {}

void expectAll(const std::vector<Eigen::Vector3d>& points, const std::vector<Surface>& surfaces,
               const PlanarEmOptions& options, Responsibilities& resp) {
  const MeasurementModel model(options.sigma_m, options.z_max_m);
  const double cutoff = model.cutoffDistance(options.responsibility_tolerance);
  const RectangleIndex index(surfaces, cutoff);
  computeResponsibilities(points, surfaces, index, model, options.responsibility_tolerance,
                          options.threads, resp);
}

void ModelSelector::expect(const std::vector<Surface>& surfaces, Responsibilities& resp) const {
  expectAll(points_, surfaces, options_, resp);
}

double ModelSelector::empty(const std::vector<std::int32_t>& members, const Rectangle& rect) const {
  return emptyArea(points_, members, rect, options_.split_cell_m);
}

std::vector<char> ModelSelector::removals(const std::vector<Surface>& surfaces,
                                          const Responsibilities& resp) {
  const std::size_t J = surfaces.size();
  const auto members = hardMembers(resp, J);
  const auto entries = entryPoints(resp, J);
  const std::vector<double> change =
      removalChanges(resp, model_.outlierScore(), J, options_.selection_scoring);
  std::vector<std::pair<double, std::size_t>> order;
  for (std::size_t j = 0; j < J; ++j) {
    const SurfaceVerdict check =
        checkSurface(measurements(), members[j], surfaces[j].rect, options_,
                     static_cast<std::size_t>(options_.min_support));
    if (check.curved) {
      for (const std::int32_t i : members[j]) {
        not_planar_[static_cast<std::size_t>(i)] = 1;  // never seed here again
      }
    }
    const double gain =
        posteriorGain(change[j], -1, -empty(members[j], surfaces[j].rect), options_);
    if (!check.valid() || raisesPosterior(gain, options_)) {
      order.emplace_back(check.valid() ? gain : std::numeric_limits<double>::infinity(), j);
    }
  }
  std::sort(order.begin(), order.end(), [](const auto& a, const auto& b) {
    return a.first > b.first || (a.first == b.first && a.second < b.second);
  });
  // Removals scored alone interact through shared points: take only
  // surfaces whose points no other removal of this pass touches.
  std::vector<char> claimed(points_.size(), 0);
  std::vector<char> drop(J, 0);
  for (const auto& [gain, j] : order) {
    const bool free = std::none_of(entries[j].begin(), entries[j].end(),
                                   [&](std::int32_t i) { return claimed[i] != 0; });
    if (free || std::isinf(gain)) {
      drop[j] = 1;
      for (const std::int32_t i : entries[j]) {
        claimed[i] = 1;
      }
    }
  }
  return drop;
}

int ModelSelector::removeSurfaces(std::vector<Surface>& surfaces, Responsibilities& resp) {
  int removed = 0;
  for (int pass = 0; pass < options_.rules.removal_passes && !surfaces.empty(); ++pass) {
    const std::vector<char> drop = removals(surfaces, resp);
    std::vector<Surface> kept;
    for (std::size_t j = 0; j < surfaces.size(); ++j) {
      if (!drop[j]) {
        kept.push_back(surfaces[j]);
      } else {
        tabu_.push_back({round_, surfaces[j].rect});
      }
    }
    const int n = static_cast<int>(surfaces.size() - kept.size());
    if (n == 0) {
      break;
    }
    removed += n;
    surfaces = std::move(kept);
    expect(surfaces, resp);
  }
  return removed;
}

const std::vector<std::int32_t>& ModelSelector::nearOf(PassCache& cache, std::size_t j) const {
  if (!cache.near[j]) {
    cache.near[j] = pointsNear(grid_, points_, cache.surfaces[j].rect, cutoff_);
  }
  return *cache.near[j];
}

double ModelSelector::emptyOf(PassCache& cache, std::size_t j) const {
  if (!cache.empty[j]) {
    cache.empty[j] = empty(cache.members[j], cache.surfaces[j].rect);
  }
  return *cache.empty[j];
}

double ModelSelector::pairLikelihoodChange(PassCache& cache, const Responsibilities& resp,
                                           std::size_t j, std::size_t k,
                                           const std::vector<Rectangle>& rects) const {
  std::vector<std::vector<std::int32_t>> near;
  for (const Rectangle& r : rects) {
    near.push_back(pointsNear(grid_, points_, r, cutoff_));
  }
  near.push_back(nearOf(cache, j));
  near.push_back(nearOf(cache, k));
  return logLikelihoodChange(points_, resp, model_, unionOf(near),
                             {static_cast<std::int32_t>(j), static_cast<std::int32_t>(k)}, rects,
                             options_.responsibility_tolerance, options_.selection_scoring);
}

// Fusion of two surfaces that are the same plane (when that raises the log
// posterior, or whatever it does when they occupy the same place:
// sameSurfacePlace), or else their re-cut: coplanar neighbours forming an L are cut
// again where the larger rectangle is largest (a canonical form: a wall or
// ceiling runs through the corner), when that costs less than min_gain.
std::optional<ModelSelector::PairChange> ModelSelector::pairChange(PassCache& cache,
                                                                   const Responsibilities& resp,
                                                                   std::size_t j,
                                                                   std::size_t k) const {
  const std::vector<Surface>& surfaces = cache.surfaces;
  const std::vector<std::vector<std::int32_t>>& members = cache.members;
  const Rectangle& a = surfaces[j].rect;
  const Rectangle& b = surfaces[k].rect;
  if (!fusionPartners(a, b, options_)) {
    return std::nullopt;
  }
  const std::vector<std::int32_t> both = unionOf({members[j], members[k]});
  Rectangle m = surfaces[members[j].size() >= members[k].size() ? j : k].rect;
  if (!fitValidSurface(measurements(), both, m, options_,
                       static_cast<std::size_t>(options_.min_support))) {
    return std::nullopt;
  }
  const double empty_before = emptyOf(cache, j) + emptyOf(cache, k);
  const double fuse_gain = posteriorGain(pairLikelihoodChange(cache, resp, j, k, {m}), -1,
                                         empty(both, m) - empty_before, options_);
  if (raisesPosterior(fuse_gain, options_) ||
      sameSurfacePlace(a, b, options_.split_min_offset_m, options_)) {
    return PairChange{1e12 + fuse_gain, j, k, {m}};
  }
  const auto recut = recutPair(both, m, std::max(members[j].size(), members[k].size()));
  if (!recut) {
    return std::nullopt;
  }
  const double empty_after =
      empty(recut->parts.part_a, recut->rects[0]) + empty(recut->parts.part_b, recut->rects[1]);
  const double gain = posteriorGain(pairLikelihoodChange(cache, resp, j, k, recut->rects), 0,
                                    empty_after - empty_before, options_);
  if (!recutAffordable(gain, options_)) {
    return std::nullopt;
  }
  return PairChange{gain, j, k, recut->rects};
}

int ModelSelector::applyPairChanges(std::vector<PairChange> changes, std::vector<Surface>& surfaces,
                                    std::int32_t& next_id) const {
  std::sort(changes.begin(), changes.end(), [](const PairChange& x, const PairChange& y) {
    return x.priority > y.priority ||
           (x.priority == y.priority && (x.j < y.j || (x.j == y.j && x.k < y.k)));
  });
  const std::size_t J = surfaces.size();
  std::vector<char> used(J, 0);
  std::vector<char> drop(J, 0);
  int changed = 0;
  for (const PairChange& c : changes) {
    if (used[c.j] || used[c.k]) {
      continue;
    }
    used[c.j] = used[c.k] = 1;
    surfaces[c.j].rect = c.replacement[0];
    surfaces[c.j].id = next_id++;
    if (c.replacement.size() > 1) {
      surfaces[c.k].rect = c.replacement[1];
      surfaces[c.k].id = next_id++;
    } else {
      drop[c.k] = 1;
    }
    ++changed;
  }
  std::vector<Surface> kept;
  for (std::size_t j = 0; j < J; ++j) {
    if (!drop[j]) {
      kept.push_back(surfaces[j]);
    }
  }
  surfaces = std::move(kept);
  return changed;
}

int ModelSelector::fuseSurfaces(std::vector<Surface>& surfaces, Responsibilities& resp,
                                std::int32_t& next_id) {
  const std::size_t J = surfaces.size();
  const auto members = hardMembers(resp, J);
  PassCache cache(surfaces, members);
  std::vector<PairChange> changes;
  for (std::size_t j = 0; j < J; ++j) {
    for (std::size_t k = j + 1; k < J; ++k) {
      if (auto c = pairChange(cache, resp, j, k)) {
        changes.push_back(std::move(*c));
      }
    }
  }
  if (changes.empty()) {
    return 0;
  }
  const int changed = applyPairChanges(std::move(changes), surfaces, next_id);
  expect(surfaces, resp);
  return changed;
}

std::optional<ModelSelector::Recut> ModelSelector::recutPair(const std::vector<std::int32_t>& both,
                                                             const Rectangle& frame,
                                                             std::size_t current_larger) const {
  const std::vector<double> no_loss(both.size(), 0.0);
  const auto cut = coverageCut(points_, both, no_loss, frame, options_.split_cell_m, 1.0, 0.0,
                               static_cast<std::size_t>(options_.min_support), false);
  if (!cut || cut->keep != CutKeep::kBoth) {
    return std::nullopt;
  }
  const std::size_t larger = std::max(cut->parts.part_a.size(), cut->parts.part_b.size());
  if (!recutGrowsLarger(larger, current_larger, options_)) {  // not clearly more canonical
    return std::nullopt;
  }
  Recut r{cut->parts, {frame, frame}};
  const auto min_points = static_cast<std::size_t>(options_.min_support);
  if (!fitValidSurface(measurements(), r.parts.part_a, r.rects[0], options_, min_points) ||
      !fitValidSurface(measurements(), r.parts.part_b, r.rects[1], options_, min_points)) {
    return std::nullopt;
  }
  return r;
}

std::vector<Rectangle> ModelSelector::settleParts(
    std::size_t j, const std::vector<Rectangle>& parts, const std::vector<std::int32_t>& affected,
    const Responsibilities& resp, std::vector<std::vector<std::int32_t>>& members) const {
  // New most likely causes of the affected points: the remaining surfaces'
  // terms and the parts (encoded as -2 - k; -1 is the outlier class).
  std::unordered_map<std::int32_t, std::int32_t> new_best;
  const double s_star = model_.outlierScore();
  for (const std::int32_t i : affected) {
    const auto p = static_cast<std::size_t>(i);
    double best = s_star;
    std::int32_t cause = -1;
    for (std::uint32_t k = resp.offsets[p]; k < resp.offsets[p + 1]; ++k) {
      if (resp.surface[k] != static_cast<std::int32_t>(j) && resp.score[k] > best) {
        best = resp.score[k];
        cause = resp.surface[k];
      }
    }
    for (std::size_t k = 0; k < parts.size(); ++k) {
      const double s = model_.surfaceScore(parts[k].squaredDistance(points_[p]));
      if (s > best) {
        best = s;
        cause = -2 - static_cast<std::int32_t>(k);
      }
    }
    new_best[i] = cause;
  }
  std::vector<std::int32_t> best = resp.best;
  for (std::int32_t& b : best) {
    b = b == static_cast<std::int32_t>(j) ? -1 : b;
  }
  members.assign(parts.size(), {});
  for (const auto& [i, cause] : new_best) {
    best[static_cast<std::size_t>(i)] = cause;
    if (cause <= -2) {
      members[static_cast<std::size_t>(-2 - cause)].push_back(i);
    }
  }
  std::vector<Rectangle> settled = parts;
  for (std::size_t k = 0; k < parts.size(); ++k) {
    std::sort(members[k].begin(), members[k].end());
    if (members[k].size() >= 3) {
      fitRectangle(
          points_,
          coherentMembers(members[k], neighbours_, best, options_.rules.coherent_neighbours),
          settled[k]);
    }
  }
  return settled;
}

std::vector<double> ModelSelector::memberLoss(const Responsibilities& resp, std::size_t j,
                                              const std::vector<std::int32_t>& members) const {
  std::vector<double> loss;
  loss.reserve(members.size());
  const double s_star = model_.outlierScore();
  for (const std::int32_t m : members) {
    const auto i = static_cast<std::size_t>(m);
    std::int64_t entry = -1;
    for (std::uint32_t k = resp.offsets[i]; k < resp.offsets[i + 1]; ++k) {
      if (resp.surface[k] == static_cast<std::int32_t>(j)) {
        entry = k;
      }
    }
    loss.push_back(pointScore(resp, i, s_star, options_.selection_scoring) -
                   pointScore(resp, i, s_star, options_.selection_scoring, entry));
  }
  return loss;
}

std::vector<std::vector<std::vector<std::int32_t>>> ModelSelector::splitOptions(
    const Surface& s, const std::vector<std::int32_t>& members, const Responsibilities& resp,
    std::size_t j) const {
  const std::size_t min_part = minSplitPart(1.0, options_);
  // Two parts, or one part (a trim: the other part's points are left to
  // whatever else explains them).
  std::vector<std::vector<std::vector<std::int32_t>>> options;
  for (const SplitProposal& p :
       residualSplits(points_, members, s.rect, options_.split_cell_m, options_.split_min_offset_m,
                      model_.sigma(), min_part, options_.rules)) {
    options.push_back({p.part_a, p.part_b});
  }
  const auto cut =
      coverageCut(points_, members, memberLoss(resp, j, members), s.rect, options_.split_cell_m,
                  options_.empty_area_cost, options_.kappa, min_part, true);
  if (cut && cut->keep == CutKeep::kBoth) {
    options.push_back({cut->parts.part_a, cut->parts.part_b});
  } else if (cut && !s.trimmed) {  // a surface is trimmed at most once
    options.push_back({cut->keep == CutKeep::kPartA ? cut->parts.part_a : cut->parts.part_b});
  }
  return options;
}

std::vector<Rectangle> ModelSelector::bestSplit(
    const std::vector<Surface>& surfaces, std::size_t j, const std::vector<std::int32_t>& members,
    const std::vector<std::vector<std::vector<std::int32_t>>>& options,
    const Responsibilities& resp) const {
  const Surface& s = surfaces[j];
  const auto old_near = pointsNear(grid_, points_, s.rect, cutoff_);
  const double old_empty = empty(members, s.rect);
  double best_gain = options_.min_gain;
  std::vector<Rectangle> best;
  for (const auto& parts : options) {
    std::vector<Rectangle> fitted;
    std::vector<std::vector<std::int32_t>> near = {old_near};
    for (const auto& part : parts) {
      Rectangle r = s.rect;
      if (!fitValidSurface(measurements(), part, r, options_,
                           static_cast<std::size_t>(options_.min_support))) {
        break;
      }
      near.push_back(pointsNear(grid_, points_, r, cutoff_));
      fitted.push_back(r);
    }
    if (fitted.size() != parts.size()) {
      continue;
    }
    // Score the state the next M-step would reach: boundary points the
    // parts would win back regrow them (a trim that would be undone gains
    // nothing).
    const std::vector<std::int32_t> affected = unionOf(near);
    std::vector<std::vector<std::int32_t>> settled_members;
    const std::vector<Rectangle> settled = settleParts(j, fitted, affected, resp, settled_members);
    double empty_after = 0.0;
    for (std::size_t k = 0; k < settled.size(); ++k) {
      empty_after += empty(settled_members[k], settled[k]);
    }
    const double gain = posteriorGain(
        logLikelihoodChange(points_, resp, model_, affected, {static_cast<std::int32_t>(j)},
                            settled, options_.responsibility_tolerance, options_.selection_scoring),
        static_cast<int>(settled.size()) - 1, empty_after - old_empty, options_);
    if (gain > best_gain &&
        std::none_of(settled.begin(), settled.end(),
                     [this](const Rectangle& r) { return isTabu(r); }) &&
        !placeTaken(settled, surfaces, j)) {
      best_gain = gain;
      best = settled;
    }
  }
  return best;
}

int ModelSelector::splitSurfaces(std::vector<Surface>& surfaces, Responsibilities& resp,
                                 std::int32_t& next_id) {
  const std::size_t J = surfaces.size();
  const auto members = hardMembers(resp, J);
  std::vector<Surface> added;
  int split = 0;
  for (std::size_t j = 0; j < J; ++j) {
    const std::vector<Rectangle> best =
        bestSplit(surfaces, j, members[j], splitOptions(surfaces[j], members[j], resp, j), resp);
    if (!best.empty()) {
      surfaces[j].rect = best[0];
      surfaces[j].id = next_id++;
      surfaces[j].trimmed = surfaces[j].trimmed || best.size() == 1;
      for (std::size_t k = 1; k < best.size(); ++k) {
        added.push_back({best[k], next_id++, 0});
      }
      ++split;
    }
  }
  if (split > 0) {
    surfaces.insert(surfaces.end(), added.begin(), added.end());
    expect(surfaces, resp);
  }
  return split;
}

int ModelSelector::seed(std::vector<Surface>& surfaces, const Responsibilities& resp,
                        std::int32_t& next_id) {
  std::vector<double> seedable = resp.outlier;
  for (std::size_t i = 0; i < seedable.size(); ++i) {
    if (not_planar_[i]) {
      seedable[i] = 0.0;
    }
  }
  const SeedResult s = seedSurfaces(
      points_, neighbours_, seedable, model_, options_,
      [this](const std::vector<std::int32_t>& m, Rectangle& r) {
        return fitValidSurface(measurements(), m, r, options_,
                               static_cast<std::size_t>(options_.min_support));
      },
      rng_);
  // Eq. (30): a new surface must raise the log posterior by more than its
  // penalty, by the same score removal uses (else it would be removed again).
  int added = 0;
  for (std::size_t k = 0; k < s.surfaces.size(); ++k) {
    const Rectangle& r = s.surfaces[k];
    const double gain = posteriorGain(
        logLikelihoodChange(points_, resp, model_, pointsNear(grid_, points_, r, cutoff_), {}, {r},
                            options_.responsibility_tolerance, options_.selection_scoring),
        1, empty(s.members[k], r), options_);
    if (raisesPosterior(gain, options_) && !isTabu(r) && !placeTaken({r}, surfaces, -1)) {
      surfaces.push_back({r, next_id++, static_cast<std::int32_t>(s.members[k].size())});
      ++added;
    }
  }
  return added;
}

int ModelSelector::prune(std::vector<Surface>& surfaces) {
  Responsibilities resp;
  expect(surfaces, resp);
  return removeSurfaces(surfaces, resp);
}

int ModelSelector::fuse(std::vector<Surface>& surfaces, std::int32_t& next_id, int passes,
                        Responsibilities& resp) {
  expect(surfaces, resp);
  int changed = 0;
  for (int pass = 0; pass < passes; ++pass) {
    const int n = fuseSurfaces(surfaces, resp, next_id);  // the E-step again when n > 0
    changed += n;
    if (n == 0) {
      break;
    }
  }
  return changed;
}

bool ModelSelector::placeTaken(const std::vector<Rectangle>& parts,
                               const std::vector<Surface>& surfaces,
                               std::ptrdiff_t replaced) const {
  const double clearance = options_.rules.same_place_clearance * options_.split_min_offset_m;
  for (std::size_t a = 0; a < parts.size(); ++a) {
    for (std::size_t b = a + 1; b < parts.size(); ++b) {
      if (sameSurfacePlace(parts[a], parts[b], clearance, options_)) {
        return true;
      }
    }
    for (std::size_t k = 0; k < surfaces.size(); ++k) {
      if (static_cast<std::ptrdiff_t>(k) != replaced &&
          sameSurfacePlace(parts[a], surfaces[k].rect, clearance, options_)) {
        return true;
      }
    }
  }
  return false;
}

// Tabu (against model-selection cycles): a surface removed in one of the
// last rules.tabu_rounds rounds may not be created again by a split or a
// seed; a split that the next round's removal undoes would otherwise repeat
// forever.
bool ModelSelector::isTabu(const Rectangle& r) const {
  return std::any_of(tabu_.begin(), tabu_.end(),
                     [&](const auto& t) { return sameAsRemoved(r, t.second, options_); });
}

SelectionChanges ModelSelector::round(std::vector<Surface>& surfaces, std::int32_t& next_id) {
  ++round_;
  while (!tabu_.empty() && tabu_.front().first < round_ - options_.rules.tabu_rounds) {
    tabu_.pop_front();
  }
  SelectionChanges c;
  Responsibilities resp;
  expect(surfaces, resp);
  c.removed = removeSurfaces(surfaces, resp);
  c.fused = fuseSurfaces(surfaces, resp, next_id);
  c.split = splitSurfaces(surfaces, resp, next_id);
  c.added = seed(surfaces, resp, next_id);
  return c;
}

}  // namespace pmap::em
