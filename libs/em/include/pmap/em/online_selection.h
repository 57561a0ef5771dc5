// The online EM's model selection (section V-C, and beyond it): the shared
// decisions of selection_policy.h applied to what the online EM can afford
// per scan. Unexplained measurements of the last scans seed new surfaces;
// surfaces without support after a grace period, or curved, are removed; and
// every surface keeps being examined for fusion (or an L re-cut) and splits,
// round robin, on a capped subsample of its points and its hull. Offline
// (model_selector.h) the same decisions look at every point every round.
#pragma once

#include <cstdint>
#include <deque>
#include <vector>

#include "pmap/em/model_selector.h"
#include "pmap/em/online_em_options.h"
#include "pmap/em/online_mstep.h"
#include "pmap/em/online_store.h"
#include "pmap/em/planar_em_options.h"

namespace pmap::em {

class OnlineSelection {
 public:
  OnlineSelection(const PlanarEmOptions& em, const OnlineEmOptions& online, OnlineStore& store,
                  OnlineMStep& mstep);

  /// Model selection before scan `scan`'s M-step: seeding (every
  /// seed_every_scans), removals, and a fusion or split turn (every
  /// select_every_scans).
  SelectionChanges select(int scan);
  /// After the M-step: the coverage cut of the first surface the M-step
  /// found poorly covered (at most one per scan); returns 1 if it split.
  int cutPoorlyCovered(int scan);
  /// Examines surface j first at the next selection turns (fusion first):
  /// its points moved (OnlineEm::movePoints).
  void prioritise(std::int32_t j);

 private:
  // Seeding and removal (online_selection.cpp).
  struct SeedWindow;
  SeedWindow seedWindow() const;
  /// The window's points and neighbour links (local indices).
  void fillWindow(SeedWindow& w) const;
  bool acceptSeed(const SeedWindow& w, const std::vector<std::int32_t>& local, Rectangle& rect);
  int seedNew();
  int removeUnsupported();
  void selectTurn(SelectionChanges& c);
  std::int32_t nextSurface();

  // Fusion and the L re-cut (online_fusion.cpp).
  bool tryFuse(std::int32_t j);
  double fusionLikelihoodChange(std::int32_t j, std::int32_t k, const Rectangle& merged,
                                const std::vector<std::int32_t>& sa,
                                const std::vector<std::int32_t>& sb) const;
  void fuse(std::int32_t j, std::int32_t k, const Rectangle& merged);
  bool tryRecut(std::int32_t j, std::int32_t k);

  // Splits (online_split.cpp).
  struct SplitSample {
    std::vector<std::int32_t> points;  ///< a capped subsample and the hull
    std::vector<double> loss;          ///< per point: worse without the surface (nats, scaled)
    double scale = 1;                  ///< members per sampled point
    double cell = 0;                   ///< grid cell of the split tests (m)
    std::size_t min_part = 0;          ///< smallest part, in sampled points
  };
  SplitSample splitSample(std::int32_t j);
  std::vector<std::vector<std::vector<std::int32_t>>> splitOptions(std::int32_t j,
                                                                   const SplitSample& x) const;
  double splitGain(std::int32_t j, const SplitSample& x,
                   const std::vector<std::vector<std::int32_t>>& parts,
                   const std::vector<Rectangle>& rects) const;
  bool trySplit(std::int32_t j);
  void applySplit(std::int32_t j, const std::vector<Rectangle>& parts);
  bool leavesUnexplained(std::int32_t j, const Rectangle& kept) const;

  PlanarEmOptions options_;
  OnlineEmOptions online_;
  OnlineStore& store_;
  OnlineMStep& mstep_;
  int scan_ = 0;
  std::size_t cursor_ = 0;             ///< round robin over surfaces
  bool fuse_turn_ = true;              ///< selection turns alternate fusion and split tests
  std::deque<std::int32_t> priority_;  ///< surfaces examined before the round robin
};

}  // namespace pmap::em
