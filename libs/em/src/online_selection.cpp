// Online model selection (section V-C, and beyond it: fusion and splits are
// not limited to a brief window but keep running round robin).
#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "pmap/em/model_selection.h"
#include "pmap/em/online_em.h"
#include "pmap/em/planarity.h"
#include "pmap/em/seeding.h"
#include "pmap/em/split_proposals.h"

namespace pmap::em {

bool OnlineEm::validSurface(const std::vector<std::int32_t>& members, const Rectangle& rect) const {
  return members.size() >= static_cast<std::size_t>(options_.min_support) &&
         distinctRows(rows_, members) >= static_cast<std::size_t>(options_.min_rows) &&
         !isCurved(measurePlanarity(points_, members, rect), options_.min_curvature_radius_m);
}

// The hard score of a point under the current map: max(s*, max_j s_ij).
double OnlineEm::hardScore(std::size_t i) const {
  const std::int32_t b = best_[i];
  return b < 0 ? model_.outlierScore()
               : model_.surfaceScore(
                     surfaces_[static_cast<std::size_t>(b)].rect.squaredDistance(points_[i]));
}

// New surfaces from the unexplained measurements of the last scans: the
// offline seeding (three adjacent poorly explained points, grown over the
// neighbour graph) on that window, kept when it raises the posterior.
int OnlineEm::seedNew() {
  std::vector<std::int32_t> global;
  for (const auto& [first, count] : window_) {
    for (std::size_t i = first; i < first + count; ++i) {
      global.push_back(static_cast<std::int32_t>(i));
    }
  }
  std::unordered_map<std::int32_t, std::int32_t> local_of;
  std::vector<Eigen::Vector3d> pts;
  std::vector<double> outlier;
  for (const std::int32_t g : global) {
    local_of[g] = static_cast<std::int32_t>(pts.size());
    pts.push_back(points_[static_cast<std::size_t>(g)]);
    // A point that stayed unexplained through kSeedTries seeding turns is not
    // seeded again (clutter, or a patch too small): bounded work per scan.
    const bool free = best_[static_cast<std::size_t>(g)] < 0 &&
                      !not_planar_[static_cast<std::size_t>(g)] &&
                      seed_tries_[static_cast<std::size_t>(g)] < kSeedTries;
    outlier.push_back(free ? 1.0 : 0.0);
  }
  if (std::count(outlier.begin(), outlier.end(), 1.0) < options_.min_support) {
    return 0;
  }
  Neighbours nb(pts.size(), {-1, -1, -1, -1});
  for (std::size_t k = 0; k < global.size(); ++k) {
    for (int s = 0; s < 4; ++s) {
      const auto it = local_of.find(neighbours_[static_cast<std::size_t>(global[k])][s]);
      nb[k][static_cast<std::size_t>(s)] = it == local_of.end() ? -1 : it->second;
    }
  }
  auto to_global = [&](const std::vector<std::int32_t>& local) {
    std::vector<std::int32_t> out;
    for (const std::int32_t l : local) {
      out.push_back(global[static_cast<std::size_t>(l)]);
    }
    return out;
  };
  auto accept = [&](const std::vector<std::int32_t>& local, Rectangle& rect) {
    if (local.size() < static_cast<std::size_t>(options_.min_support) ||
        fitSurface(pts, local, rect) != FitStatus::kOk) {
      return false;
    }
    const std::vector<std::int32_t> g = to_global(local);
    if (isCurved(measurePlanarity(points_, g, rect), options_.min_curvature_radius_m)) {
      for (const std::int32_t i : g) {
        not_planar_[static_cast<std::size_t>(i)] = 1;  // a bin: do not try here again
      }
      return false;
    }
    return distinctRows(rows_, g) >= static_cast<std::size_t>(options_.min_rows);
  };
  PlanarEmOptions seeding = options_;
  seeding.max_new_per_round = 2;
  const SeedResult s = seedSurfaces(pts, nb, outlier, model_, seeding, accept, rng_, kSeedAttempts);
  for (std::size_t k = 0; k < global.size(); ++k) {
    if (outlier[k] > 0.0) {
      ++seed_tries_[static_cast<std::size_t>(global[k])];
    }
  }
  int added = 0;
  for (std::size_t k = 0; k < s.surfaces.size(); ++k) {
    const std::vector<std::int32_t> members = to_global(s.members[k]);
    double gain =
        -options_.kappa - options_.empty_area_cost *
                              emptyArea(points_, members, s.surfaces[k], options_.split_cell_m);
    for (const std::int32_t i : members) {
      gain +=
          model_.surfaceScore(s.surfaces[k].squaredDistance(points_[static_cast<std::size_t>(i)])) -
          model_.outlierScore();
    }
    if (gain > options_.min_gain) {
      createSurface(s.surfaces[k], members);
      ++added;
    }
  }
  return added;
}

// Surfaces still below min_support after removal_after_scans scans, or
// curved, are removed; their points go back to the revisit queue.
int OnlineEm::removeUnsupported() {
  int removed = 0;
  for (std::size_t j = 0; j < surfaces_.size(); ++j) {
    OnlineSurface& s = surfaces_[j];
    if (!s.alive) {
      continue;
    }
    const bool old = scans_ - s.created_scan >= online_.removal_after_scans;
    bool drop = old && s.members.size() < static_cast<std::size_t>(options_.min_support);
    if (!drop && s.active) {
      const std::vector<std::int32_t> sample = sampleMembers(s, online_.sample_cap);
      if (isCurved(measurePlanarity(points_, sample, s.rect), options_.min_curvature_radius_m)) {
        for (const std::int32_t i : s.members) {
          not_planar_[static_cast<std::size_t>(i)] = 1;
        }
        drop = true;
      }
    }
    if (drop) {
      removeSurface(static_cast<std::int32_t>(j));
      ++removed;
    }
  }
  return removed;
}

void OnlineEm::selectRoundRobin(SelectionChanges& c) {
  for (int k = 0; k < online_.selection_per_scan && !surfaces_.empty(); ++k) {
    std::size_t tries = 0;
    do {
      cursor_ = (cursor_ + 1) % surfaces_.size();
    } while (!surfaces_[cursor_].alive && ++tries < surfaces_.size());
    if (!surfaces_[cursor_].alive) {
      return;
    }
    // Fusion and split tests take turns, so that one scan pays for one of them.
    const auto j = static_cast<std::int32_t>(cursor_);
    if (fuse_turn_) {
      c.fused += tryFuse(j) ? 1 : 0;
    } else {
      c.split += trySplit(j) ? 1 : 0;
    }
    fuse_turn_ = !fuse_turn_;
  }
}

}  // namespace pmap::em
