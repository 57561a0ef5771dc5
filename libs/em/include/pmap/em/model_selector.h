// One round of model selection (eq. 30): remove, fuse and split surfaces
// when that raises the log posterior, then seed new ones.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <deque>
#include <optional>
#include <random>
#include <vector>

#include "pmap/em/measurement_model.h"
#include "pmap/em/neighbours.h"
#include "pmap/em/planar_em_options.h"
#include "pmap/em/point_grid.h"
#include "pmap/em/responsibilities.h"
#include "pmap/em/selection_policy.h"
#include "pmap/em/split_proposals.h"
#include "pmap/em/surface.h"

namespace pmap::em {

struct SelectionChanges {
  int removed = 0;
  int fused = 0;
  int split = 0;
  int added = 0;
  bool any() const { return removed + fused + split + added > 0; }
};

/// The E-step (eqs. 17-18) of `surfaces` over `points` under the measurement
/// model of `options`: ModelSelector::expect without a selector's point grid
/// (a final assignment over many points).
void expectAll(const std::vector<Eigen::Vector3d>& points, const std::vector<Surface>& surfaces,
               const PlanarEmOptions& options, Responsibilities& resp);

class ModelSelector {
 public:
  /// `rows` (may be empty): each point's row (scan) for the min_rows test.
  ModelSelector(const std::vector<Eigen::Vector3d>& points, const Neighbours& neighbours,
                const std::vector<std::int32_t>& rows, const PlanarEmOptions& options);

  /// Runs a round on `surfaces`; `next_id` gives ids to new surfaces.
  SelectionChanges round(std::vector<Surface>& surfaces, std::int32_t& next_id);

  /// Removes the surfaces that are invalid or whose removal raises the log
  /// posterior (the removal step of a round alone); returns how many.
  int prune(std::vector<Surface>& surfaces);

  /// The fusion step of a round alone, up to `passes` times while pairs
  /// change (E-step, then fuse or re-cut pairs of coplanar neighbours when
  /// that raises the log posterior); returns how many pairs changed, with
  /// `resp` the E-step of the final `surfaces`.
  int fuse(std::vector<Surface>& surfaces, std::int32_t& next_id, int passes,
           Responsibilities& resp);

  /// E-step on `surfaces` with this selector's index settings.
  void expect(const std::vector<Surface>& surfaces, Responsibilities& resp) const;

  const MeasurementModel& model() const { return model_; }
  double cutoff() const { return cutoff_; }

 private:
  int removeSurfaces(std::vector<Surface>& surfaces, Responsibilities& resp);
  int fuseSurfaces(std::vector<Surface>& surfaces, Responsibilities& resp, std::int32_t& next_id);
  int splitSurfaces(std::vector<Surface>& surfaces, Responsibilities& resp, std::int32_t& next_id);
  int seed(std::vector<Surface>& surfaces, const Responsibilities& resp, std::int32_t& next_id);

  /// The surfaces to remove in one pass: invalid ones, and those whose
  /// removal raises the log posterior, without two sharing a point.
  std::vector<char> removals(const std::vector<Surface>& surfaces, const Responsibilities& resp);
  struct PairChange {
    double priority;  ///< fusions first, then by gain
    std::size_t j, k;
    std::vector<Rectangle> replacement;  ///< one rectangle (fusion) or two (re-cut)
  };
  /// What the pairs of one fusion pass share: each surface's points within
  /// the cutoff and its members' empty area, computed on first use.
  struct PassCache {
    const std::vector<Surface>& surfaces;
    const std::vector<std::vector<std::int32_t>>& members;
    std::vector<std::optional<std::vector<std::int32_t>>> near;
    std::vector<std::optional<double>> empty;
    PassCache(const std::vector<Surface>& s, const std::vector<std::vector<std::int32_t>>& m)
        : surfaces(s), members(m), near(s.size()), empty(s.size()) {}
  };
  const std::vector<std::int32_t>& nearOf(PassCache& cache, std::size_t j) const;
  double emptyOf(PassCache& cache, std::size_t j) const;
  /// The fusion or re-cut of surfaces j and k, when it is to be made.
  std::optional<PairChange> pairChange(PassCache& cache, const Responsibilities& resp,
                                       std::size_t j, std::size_t k) const;
  /// Log-likelihood change (eq. 30's first term) of replacing surfaces j
  /// and k by `rects`.
  double pairLikelihoodChange(PassCache& cache, const Responsibilities& resp, std::size_t j,
                              std::size_t k, const std::vector<Rectangle>& rects) const;
  /// Makes the non-overlapping `changes` (best first); returns how many.
  int applyPairChanges(std::vector<PairChange> changes, std::vector<Surface>& surfaces,
                       std::int32_t& next_id) const;
  /// The candidate replacements of surface j: residual splits, the best
  /// coverage cut (two parts) or trim (one part, unless j was trimmed).
  std::vector<std::vector<std::vector<std::int32_t>>> splitOptions(
      const Surface& s, const std::vector<std::int32_t>& members, const Responsibilities& resp,
      std::size_t j) const;
  /// The best replacement of surface j among `options` (empty: none gains).
  std::vector<Rectangle> bestSplit(
      const std::vector<Surface>& surfaces, std::size_t j, const std::vector<std::int32_t>& members,
      const std::vector<std::vector<std::vector<std::int32_t>>>& options,
      const Responsibilities& resp) const;

  /// Rectangle area (m^2) that `members` leave empty.
  double empty(const std::vector<std::int32_t>& members, const Rectangle& rect) const;
  Measurements measurements() const { return {points_, rows_}; }
  struct Recut {
    SplitProposal parts;
    std::vector<Rectangle> rects;
  };
  /// The union of two coplanar surfaces cut again into two rectangles, when
  /// the larger one grows clearly beyond `current_larger` points.
  std::optional<Recut> recutPair(const std::vector<std::int32_t>& both, const Rectangle& frame,
                                 std::size_t current_larger) const;
  /// The rectangles `parts` (replacing surface j) after one hard
  /// reassignment of the `affected` points and a coherent rectangle refit,
  /// i.e. where the next M-step would take them; `members` gets their points.
  std::vector<Rectangle> settleParts(std::size_t j, const std::vector<Rectangle>& parts,
                                     const std::vector<std::int32_t>& affected,
                                     const Responsibilities& resp,
                                     std::vector<std::vector<std::int32_t>>& members) const;
  /// Per member of surface j: how much worse it is scored without j.
  std::vector<double> memberLoss(const Responsibilities& resp, std::size_t j,
                                 const std::vector<std::int32_t>& members) const;

  const std::vector<Eigen::Vector3d>& points_;
  const Neighbours& neighbours_;
  const std::vector<std::int32_t>& rows_;
  PlanarEmOptions options_;
  MeasurementModel model_;
  double cutoff_;
  PointGrid grid_;
  bool isTabu(const Rectangle& r) const;
  /// Whether new rectangles `parts` (replacing surface `replaced`, -1: none)
  /// would occupy the same place as each other or as another surface
  /// (sameSurfacePlace): such a change is not made.
  bool placeTaken(const std::vector<Rectangle>& parts, const std::vector<Surface>& surfaces,
                  std::ptrdiff_t replaced) const;

  int round_ = 0;
  std::deque<std::pair<int, Rectangle>> tabu_;  ///< (round, rectangle) of recent removals
  /// Points of surfaces removed as curved (a bin): not seeded again.
  std::vector<char> not_planar_;
  std::mt19937_64 rng_;
};

}  // namespace pmap::em
