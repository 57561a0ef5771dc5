// Options of the offline EM planar mapper ([PlanarEM] in the ini; loaded by
// the mapper, this library depends on Eigen alone).
#pragma once

#include <cstdint>
#include <string>

#include "pmap/em/selection_rules.h"

namespace pmap::em {

struct PlanarEmOptions {
  // Every threshold of the EM and its model selection lives here (the fixed
  // ones in `rules`), shared by the offline and the online EM; the online
  // EM's work bounds are OnlineEmOptions. Per field: units, range, and why
  // this value ("measured with": the figures of doc/RESULTS.md use it).

  // Measurement model, eqs. (9)-(11).
  /// Range noise sigma (m), > 0: the laser's specification (2 cm; 5 cm for
  /// the paper's SICK PLS, config/sigma5.ini).
  double sigma_m = 0.02;
  /// `sigma_m = auto`: sigma_m is estimated from the data before the EM
  /// runs (noise_estimate.h; the online EM waits for its first
  /// auto_sigma_points measurements), and reported in summary.json.
  bool sigma_auto = false;
  /// With sigma_auto: measurements the online EM collects before it
  /// estimates sigma and starts, >= 100.
  int auto_sigma_points = 20000;
  /// Sensor range of the uniform outlier density (m), > 3 sigma: the
  /// laser's maximum range. With sigma it sets the outlier distance
  /// sigma sqrt(L*) (7.2 cm at 2 cm, 16.5 cm at 5 cm).
  double z_max_m = 30.0;

  // Model selection, eq. (30).
  /// Log-posterior penalty per surface (nats), >= 0: a point on a plane
  /// gains L*/2 = 6.4 nats over the outlier class at sigma 2 cm, so a
  /// surface must explain about 30 points perfectly to pay for itself; small
  /// enough for a door, large enough that noise does not buy surfaces.
  double kappa = 200.0;
  /// Run model selection every K iterations, >= 1: the M-step settles the
  /// surfaces between rounds, so a round judges converged geometry.
  int selection_interval = 5;
  /// Cap of new surfaces seeded per round, >= 1: a work bound (the worlds
  /// of doc/RESULTS.md have at most 22 surfaces to find).
  int max_new_per_round = 20;
  /// e_i* (outlier responsibility) above which a point is poorly explained
  /// and may seed, in (0, 1): more likely an outlier than not (section IV-C).
  double seed_outlier_probability = 0.5;
  /// Fewest points a (new or kept) surface must explain, >= 3: with kappa,
  /// a surface of fewer points is clutter (a chair leg, a strip of a door
  /// frame) better left to the fine triangles.
  int min_support = 60;
  /// Fewest distinct rows (scans) a surface's points must come from, >= 1.
  /// One vertical scan is itself an exact plane; a surface seen by only one
  /// or two scans is that artefact, not a wall. Used when the input carries
  /// rows.
  int min_rows = 5;
  /// How model selection scores a change: kHard (default) scores each point
  /// by its most likely cause, max(s*, max_j s_ij); kSoft by the mixture
  /// log(exp(s*) + sum_j exp(s_ij)). Soft scoring rewards a redundant copy
  /// of a surface by up to log 2 nats per shared point, so redundant surfaces
  /// of fewer than kappa / log 2 points can never be removed (doc/em.md).
  enum class Scoring { kHard, kSoft };
  Scoring selection_scoring = Scoring::kHard;
  /// A model-selection change is made only when it raises the log posterior
  /// by more than this (nats), >= 0: hysteresis against changes that the
  /// next M-step undoes (a trim of a few centimetres that boundary points
  /// regrow); 10 nats are one or two points' worth at sigma 2 cm.
  double min_gain = 10.0;
  /// A surface whose points bend with a smaller radius (a bin, a column) is
  /// not a plane (planarity.h) and is not kept (m), > 0: a wall does not
  /// bend measurably, a bin or a column bends with a radius well under 1 m.
  double min_curvature_radius_m = 1.0;
  /// ... and only when the bend is at least this deep across the surface
  /// (its sagitta, planarity.h) (m), >= 0. 0 (default): any depth, so a
  /// bin's strip a plane explains is curved however narrow. A sensor whose
  /// systematic error bends flat surfaces sets it above that bend: a range
  /// camera's depth distortion bends a wall 1-2.5 cm deep on MRPT's Kinect
  /// frame (config/mrpt-rgbd.ini: 0.04); on the simulated worlds at sigma
  /// 5 cm a bin's strips are 6.7-13 cm deep, so 2 sigma there would keep
  /// bins as planes (doc/em.md).
  double min_curvature_depth_m = 0.0;
  // Fusion of surfaces that are the same plane: candidate pairs only (the
  // posterior decides); loose enough for two halves of one wall fitted
  // from noisy, partial views.
  double fuse_angle_deg = 10.0;  ///< normals closer than this may fuse (deg)
  double fuse_offset_m = 0.10;   ///< planes closer than this at each other's centres (m)
  double fuse_gap_m = 0.5;       ///< rectangles closer than this in the plane (m)
  // Split tests (beyond the paper).
  /// Patch size of the residual / coverage grids (m), > 0: about two scan
  /// spacings (8 cm between scans in the simulated worlds), so a patch that
  /// was seen has no empty cell.
  double split_cell_m = 0.15;
  /// A patch's mean residual must exceed this (m), > 0: 4 cm separates a
  /// door recessed by 10 cm from its wall at sigma 5 cm, yet not a wall's
  /// unevenness.
  double split_min_offset_m = 0.04;
  /// Prior cost of rectangle area no point covers (nats/m^2), >= 0:
  /// 10 m^2 of empty rectangle cost as much as a surface (kappa), so the box
  /// of an L-shaped ceiling is cut in two, while a few empty grid cells
  /// (gaps between scans, 0.02 m^2 each) cost less than a nat.
  double empty_area_cost = 20.0;
  /// The fixed thresholds of model selection (not read from the ini), each
  /// with its reason: selection_rules.h.
  SelectionRules rules;

  // Iterations and convergence.
  int max_iterations = 200;  ///< hard cap, >= 1: a bound; runs converge well before it
  /// Relative change of the log posterior below which an iteration counts
  /// as converged (1e-6: far below a point's worth of nats).
  double convergence_tolerance = 1e-6;
  /// ... or an absolute change below this (nats): the hard rectangle fit can
  /// settle into a two-state flip of one boundary point (a fraction of a nat).
  double convergence_absolute_nats = 1.0;
  /// Iterations in a row below the tolerance, >= 1: one quiet iteration
  /// after a model-selection round is not yet convergence.
  int convergence_patience = 3;
  /// Surfaces whose terms fall below this fraction of the outlier term are
  /// skipped in the E-step (their responsibility is below it), in (0, 1):
  /// 1e-6 changes no weight that matters and bounds the work per point.
  double responsibility_tolerance = 1e-6;
  /// Coarse-to-fine offline EM (offline_em.h), 0 or >= 1000: an input of
  /// more than twice this many points runs the EM with its model selection
  /// on a uniform random sample of this many (subsample.h: the thresholds
  /// that count points or nats scaled to it), then at most fine_iterations
  /// E- and M-steps on all points from the sample's surfaces, then the
  /// removal test on all points. 0: every iteration on all points (the
  /// default: the simulated scans of doc/RESULTS.md are mapped as before).
  /// A range camera's frame holds 300k points on a few square metres, far
  /// more than model selection needs to decide (config/mrpt-rgbd.ini).
  int coarse_points = 0;
  /// E- and M-steps on all points after the sample's EM, >= 1: the first
  /// ones fit each surface to its full set of points (the sample's planes
  /// and boundaries are within a sample spacing of them); later ones only
  /// creep: on the Kinect frame the clutter surfaces that share points kept
  /// moving by degrees over 80 more iterations while the explained share
  /// changed by 0.2 % (doc/real-geometry.md).
  int fine_iterations = 5;
  /// Spatial blocks (offline_em.h, spatial_blocks.h), 0 or >= 10000: an
  /// input of more than twice this many points is cut into blocks of at
  /// most this many (median cuts along the longer horizontal side), each
  /// mapped on its own with the points within block_margin_m of it, so
  /// that the work grows with the points, not with points x surfaces.
  /// 0: one block (the default). coarse_points applies to a run in one
  /// block; blocks use block_coarse_points instead.
  int block_points = 0;
  /// Each block's coarse_points, 0 or >= 1000: a sample of the same size in
  /// every block keeps its density whatever the building's size (one
  /// sample of a whole 5M-point building is one point in fifty).
  int block_coarse_points = 0;
  /// A block's margin (m), >= 0: how far past its seams a block sees, so
  /// that a surface cut by a seam is fitted on both sides of it.
  double block_margin_m = 1.0;
  bool bounded = true;          ///< false: unbounded planes (property tests)
  bool model_selection = true;  ///< false: J fixed to the initial surfaces
  /// Longest edge of a fine triangle (m), > 0: a few beam spacings, so
  /// triangles bridge neighbouring outliers but not gaps between objects.
  double fine_max_edge_m = 0.15;
  /// Fine triangles from outliers thinned to one per cube of this side (m),
  /// 0 or in (0, fine_max_edge_m): 0 is the paper's method (every outlier a
  /// vertex). fine_triangles.h; doc/em.md, "Fine triangles".
  double fine_cell_m = 0.0;
  std::uint64_t seed = 1;  ///< random choices (seed selection)
  int threads = 1;         ///< >= 1; results do not depend on it

  bool validate(std::string* why) const;
};

}  // namespace pmap::em
