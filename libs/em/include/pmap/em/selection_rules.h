// The fixed thresholds of model selection (eq. 30 and the rules beyond the
// paper), each with the reason for its value. The thresholds tuned per data
// set (kappa, min_gain, empty_area_cost, min_support, min_rows,
// min_curvature_radius_m, fuse_*, split_*) sit beside them in
// PlanarEmOptions, which holds this struct: one options struct for every
// decision, shared by the offline and the online EM (selection_policy.h).
// The online EM's work bounds (how much it looks at per scan) are
// OnlineEmOptions. doc/em.md lists them all in one table.
#pragma once

#include <string>

namespace pmap::em {

struct SelectionRules {
  /// A point belongs to a plane when a region is grown from a seed, or a new
  /// measurement continues its neighbour's surface online, within this many
  /// sigma of the plane: 98.8 % of a surface's own points, while a door 10 cm
  /// behind its wall (5 sigma at 2 cm) is not taken.
  double grow_sigmas = 2.5;
  /// A re-cut of two coplanar surfaces into the canonical form (the larger
  /// one runs through the corner of an L) must grow the larger one by more
  /// than this percentage of its points: moving a fringe of boundary points
  /// is not clearly more canonical, and would flip back and forth between
  /// rounds as the boundary points do.
  int recut_min_growth_percent = 5;
  /// An online re-cut that transfers points (cornerTransfer) moves at most
  /// this percentage of the smaller surface's points: moving nearly all of
  /// them is a fusion, which the fusion test has just rejected. (The offline
  /// re-cut re-partitions the union and requires both parts to be valid
  /// surfaces instead.)
  int recut_max_transfer_percent = 90;
  /// Removal passes per offline round: removals scored alone interact
  /// through shared points, so each pass takes only non-overlapping ones
  /// and the next pass re-scores; 4 settles the worlds of doc/RESULTS.md.
  int removal_passes = 4;
  /// Tabu against model-selection cycles (offline): a surface removed in one
  /// of the last `tabu_rounds` rounds may not be created again by a split or
  /// a seed. "Again" = normals within `tabu_angle_deg`, centre within
  /// `tabu_offset_sigmas` sigma of the removed plane and within
  /// `tabu_centre_m` + `tabu_centre_per_side` * sqrt(area) of its centre.
  int tabu_rounds = 3;
  double tabu_angle_deg = 5.0;
  double tabu_offset_sigmas = 2.0;
  double tabu_centre_m = 0.1;
  double tabu_centre_per_side = 0.25;
  /// Online: a surface whose refitted rectangle its points leave mostly
  /// empty (more than `poor_coverage_empty_fraction` of its area, on cells
  /// holding ~4 sampled points each) is tested for a coverage cut at once,
  /// before it spreads further (a ceiling continued around a corner). Only
  /// rectangles of at least `poor_coverage_min_area_m2` with at least
  /// `poor_coverage_min_points` sampled points are judged (a small or barely
  /// seen surface is not yet evidence of an L).
  double poor_coverage_min_area_m2 = 4.0;
  int poor_coverage_min_points = 32;
  double poor_coverage_empty_fraction = 0.5;
  /// A split part on a subsample must hold at least this many sampled points
  /// (besides min_support scaled to the sample): fewer do not fix a plane
  /// and a grid cell reliably.
  int min_part_points = 8;
  /// Online split tests run on a subsample: their grid cells are at least
  /// this many mean point spacings wide, so that a subsample still covers a
  /// fully seen surface (else every cell between sampled points looks empty).
  double sampled_cell_spacings = 1.5;
  /// The rectangle (eq. 29) is fitted to the members whose most likely
  /// cause is shared by at least this many of their 4 grid neighbours
  /// (coherentMembers): a few noisy wall points next to a door opening,
  /// claimed by the door, would otherwise stretch the door over the wall;
  /// 2 still keeps the points of a straight edge (3) and of a corner (2).
  int coherent_neighbours = 2;
  /// A surface bending with a radius below min_curvature_radius_m is curved
  /// only when the bend explains at least this share of its residual
  /// variance: below it the fitted curvature is the noise of a flat wall.
  double curved_min_variance_explained = 0.25;
  /// Residual-patch splits (split_proposals.h): the grid cell holds at least
  /// `residual_cell_points` points on average, so a patch's mean residual is
  /// known to ~sigma/5; a cell counts with at least
  /// `residual_min_cell_points` points (fewer are noise-thinned edges) and
  /// is off the plane when its mean residual exceeds split_min_offset_m and
  /// `residual_sigmas` * sigma / sqrt(points) (4: a cell of a flat wall
  /// passes by chance with probability 6e-5).
  double residual_cell_points = 24.0;
  int residual_min_cell_points = 8;
  double residual_sigmas = 4.0;
  /// Online L re-cut (cornerTransfer, coverage_cut.h): the larger surface's
  /// width is measured on its points within `corner_end_window_m` of its
  /// end (a rectangle turned by a fraction of a degree would narrow it);
  /// the other surface must reach `corner_min_leg_beyond_m` beyond that
  /// width (collinear pieces of one corridor are no L); the moved points
  /// must lie on the larger plane (at least `corner_on_plane_percent` within
  /// grow_sigmas: a door behind its wall is no L) and beyond its end (at most
  /// `corner_beside_percent` more than `corner_beside_margin_m` before the
  /// end: a room's ceiling seen next to a corridor's is no L).
  double corner_end_window_m = 1.0;
  double corner_min_leg_beyond_m = 0.5;
  int corner_on_plane_percent = 90;
  int corner_beside_percent = 10;
  double corner_beside_margin_m = 0.1;
  /// Two surfaces occupy the same place (sameSurfacePlace) when, besides
  /// normals within fuse_angle_deg, one rectangle covers at least
  /// `same_place_overlap_percent` of the smaller one's area (25: on the
  /// Kinect frame mapped with every point, the wall came out as two pieces
  /// interleaved along a diagonal band, their rectangles overlapping by
  /// more than a quarter and less than half) and their planes
  /// are within split_min_offset_m of each other all over that overlap:
  /// surfaces are opaque, a sensor cannot see two of them at the same
  /// place, and the split test would not cut a patch that close off a
  /// surface either. Such a pair is one surface whose points deviate from a
  /// plane in a way the model does not describe (a range camera's depth
  /// distortion and disparity staircase, a slightly bent wall); it is fused
  /// whatever the likelihood says. A new surface (seed or split part) must
  /// stand clear of every surface it overlaps so by more than
  /// `same_place_clearance` times split_min_offset_m (hysteresis: a part
  /// created just beyond the fusion distance would be pulled within it by
  /// the next M-steps, fused, and created again). A door 10 cm behind its
  /// wall is created and kept (6 cm at the default 4 cm).
  int same_place_overlap_percent = 25;
  double same_place_clearance = 1.5;
  /// Offline seeding work bound: seed triples grown per round, per surface
  /// the round may add (max_new_per_round); most grown regions fail the
  /// validity or the posterior test (the value of the starting code).
  int seed_attempts_per_surface = 20;

  bool validate(std::string* why) const;
};

}  // namespace pmap::em
