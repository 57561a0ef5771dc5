// Options of the offline EM planar mapper ([PlanarEM] in the ini; loaded by
// the mapper, this library depends on Eigen alone).
#pragma once

#include <cstdint>
#include <string>

namespace pmap::em {

struct PlanarEmOptions {
  // Measurement model, eqs. (9)-(11).
  double sigma_m = 0.02;  ///< range noise sigma (m), > 0
  double z_max_m = 30.0;  ///< sensor range of the uniform outlier density (m), > sigma

  // Model selection, eq. (30).
  double kappa = 200.0;                   ///< log-posterior penalty per surface (nats), >= 0
  int selection_interval = 5;             ///< run model selection every K iterations, >= 1
  int max_new_per_round = 20;             ///< cap of new surfaces seeded per round, >= 1
  double seed_outlier_probability = 0.5;  ///< e_i* above which a point is poorly explained
  int min_support = 60;  ///< fewest points a (new or kept) surface must explain, >= 3
  /// Fewest distinct rows (scans) a surface's points must come from. One
  /// vertical scan is itself an exact plane; a surface seen by only one or two
  /// scans is that artefact, not a wall. Used when the input carries rows.
  int min_rows = 5;
  /// How model selection scores a change: kHard (default) scores each point
  /// by its most likely cause, max(s*, max_j s_ij); kSoft by the mixture
  /// log(exp(s*) + sum_j exp(s_ij)). Soft scoring rewards a redundant copy
  /// of a surface by up to log 2 nats per shared point, so redundant surfaces
  /// of fewer than kappa / log 2 points can never be removed (doc/em.md).
  enum class Scoring { kHard, kSoft };
  Scoring selection_scoring = Scoring::kHard;
  /// A model-selection change is made only when it raises the log posterior
  /// by more than this (nats): hysteresis against changes that the next
  /// M-step undoes (a trim of a few centimetres that boundary points regrow).
  double min_gain = 10.0;
  /// A surface whose points bend with a smaller radius (a bin, a column) is
  /// not a plane (planarity.h) and is not kept (m).
  double min_curvature_radius_m = 1.0;
  // Fusion of surfaces that are the same plane.
  double fuse_angle_deg = 10.0;  ///< normals closer than this may fuse
  double fuse_offset_m = 0.10;   ///< planes closer than this (at each other's centres)
  double fuse_gap_m = 0.5;       ///< rectangles closer than this (in the plane)
  // Split tests (beyond the paper).
  double split_cell_m = 0.15;        ///< patch size of the residual / coverage grids (m)
  double split_min_offset_m = 0.04;  ///< a patch's mean residual must exceed this (m)
  double empty_area_cost = 20.0;     ///< prior cost of rectangle area no point covers (nats/m^2)

  // Iterations and convergence.
  int max_iterations = 200;             ///< hard cap, >= 1
  double convergence_tolerance = 1e-6;  ///< relative change of the log posterior
  /// ... or an absolute change below this (nats): the hard rectangle fit can
  /// settle into a two-state flip of one boundary point (a fraction of a nat).
  double convergence_absolute_nats = 1.0;
  int convergence_patience = 3;  ///< iterations in a row below the tolerance
  /// Surfaces whose terms fall below this fraction of the outlier term are
  /// skipped in the E-step (their responsibility is below it).
  double responsibility_tolerance = 1e-6;
  bool bounded = true;            ///< false: unbounded planes (property tests)
  bool model_selection = true;    ///< false: J fixed to the initial surfaces
  double fine_max_edge_m = 0.15;  ///< longest edge of a fine triangle (m)
  std::uint64_t seed = 1;         ///< random choices (seed selection)
  int threads = 1;                ///< >= 1; results do not depend on it

  bool validate(std::string* why) const;
};

}  // namespace pmap::em
