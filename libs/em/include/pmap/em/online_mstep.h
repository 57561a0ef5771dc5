// The online EM's surfaces and their incremental M-step (paper section V):
// only active surfaces (an assignment moved to or from them) are refitted,
// from hard assignments: the plane from the store's exact sufficient
// statistics (eqs. 24-27), the rectangle (eq. 29) from the surface's previous
// hull, its newest members and a seeded random subsample capped at
// `sample_cap`, so the extent is kept without refitting every point. Also
// the E-step of one measurement over the surfaces a hashed index lists.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <random>
#include <vector>

#include "pmap/em/incremental_index.h"
#include "pmap/em/measurement_model.h"
#include "pmap/em/online_em_options.h"
#include "pmap/em/online_store.h"
#include "pmap/em/planar_em_options.h"
#include "pmap/em/rectangle.h"

namespace pmap::em {

/// A surface of the online map: its geometry and bookkeeping (its members
/// and statistics are in the store, same slot number).
struct OnlineSurface {
  Rectangle rect;
  std::int32_t id = -1;
  std::vector<std::int32_t> hull;  ///< members on the last rectangle's hull
  int created_scan = 0;
  bool alive = true;
  bool trimmed = false;
  bool poorly_covered = false;  ///< the last M-step left most of the rectangle empty
  /// Members when a cut of this poorly covered surface last found nothing
  /// (0: never): the next try waits for min_support more (cutPoorlyCovered).
  std::size_t cut_refused_members = 0;
};

/// The most likely cause of a measurement and how clearly it wins.
struct Cause {
  std::int32_t best = -1;
  double best_score = 0;
  double margin = 0;  ///< best minus second-best score (nats)
};

class OnlineMStep {
 public:
  OnlineMStep(const PlanarEmOptions& em, const OnlineEmOptions& online, OnlineStore& store);

  /// E-step of measurement i, eqs. (17)-(18) with hard scores.
  Cause evaluate(std::size_t i) const;
  /// Beyond the paper: the surface of an adjacent measurement whose plane
  /// measurement i lies on (within rules.grow_sigmas), or -1.
  std::int32_t continuation(std::size_t i) const;
  /// The M-step of every alive active surface; returns how many.
  int maximizeActive();
  /// The M-step of surface j.
  void maximize(std::int32_t j);

  /// Up to `cap` members of surface j, a seeded random subsample, ascending.
  std::vector<std::int32_t> sampleMembers(std::int32_t j, int cap);
  /// A new surface with `rect`, taking `members`; returns its slot.
  std::int32_t create(const Rectangle& rect, const std::vector<std::int32_t>& members, int scan);
  /// Removes surface j; its members become outliers and are queued with a
  /// fresh visit count.
  void remove(std::int32_t j);
  /// Gives surface j a new rectangle (and index entry).
  void reshape(std::int32_t j, const Rectangle& rect);
  std::int32_t newId() { return next_id_++; }

  std::size_t slots() const { return surfaces_.size(); }
  OnlineSurface& surface(std::int32_t j) { return surfaces_[static_cast<std::size_t>(j)]; }
  const OnlineSurface& surface(std::int32_t j) const {
    return surfaces_[static_cast<std::size_t>(j)];
  }
  int aliveCount() const;
  const IncrementalIndex& index() const { return index_; }
  const MeasurementModel& model() const { return model_; }
  /// The hard score of measurement i under the current map, max(s*, s_ib).
  double score(std::size_t i, const Rectangle& r) const {
    return model_.surfaceScore(r.squaredDistance(store_.point(i)));
  }
  std::mt19937_64& rng() { return rng_; }

 private:
  /// The previous hull, the newest members and a subsample of surface j.
  std::vector<std::int32_t> rectangleBasis(std::int32_t j);

  PlanarEmOptions options_;
  OnlineEmOptions online_;
  OnlineStore& store_;
  MeasurementModel model_;
  IncrementalIndex index_;
  std::mt19937_64 rng_;
  std::vector<OnlineSurface> surfaces_;
  std::int32_t next_id_ = 0;
  /// evaluate()'s candidate list, kept between calls: one allocation, not
  /// one per measurement (the online EM runs on one thread).
  mutable std::vector<std::int32_t> candidates_;
};

}  // namespace pmap::em
