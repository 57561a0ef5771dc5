// Options of the refinement stage ([Refinement] in the ini; loaded by the
// mapper, this library knows nothing of ini files). doc/refinement.md.
#pragma once

#include <string>

namespace pmap::refine {

struct RefineOptions {
  bool enabled = true;  ///< false: the EM's map is written as it is
  bool fuse = true;     ///< fuse surfaces that are the same plane (eq. 30)
  /// Fusion tolerances in units of the EM's sigma: planes within
  /// fuse_sigmas * sigma of each other's centres, normals within
  /// atan(fuse_sigmas * sigma / 1 m) (the tilt that moves a point 1 m away by
  /// the offset tolerance), > 0.
  double fuse_sigmas = 5.0;
  /// A rectangle edge within this of a non-parallel surface's plane, and
  /// along the planes' intersection line, ends on that line (m), > 0.
  double seam_distance_m = 0.3;
  /// The part of an edge beside the other rectangle must be at least this
  /// long (m), >= 0: rectangles touching at a corner point do not meet.
  double seam_min_length_m = 0.1;
  /// Surfaces whose normals are closer than this are parallel: no seam
  /// between them (deg), in (0, 90).
  double seam_min_angle_deg = 30.0;
  /// An edge's 15-degree cone around the intersection line: edges at a larger
  /// angle to the line are not seams (deg), in (0, 90).
  double seam_max_edge_angle_deg = 15.0;
  /// How tightly an edge ends on its seam: residual scale of the corner's
  /// distance to the other plane (m), > 0.
  double seam_sigma_m = 0.002;
  /// A seam's residual is quadratic up to about this distance and pulls
  /// ever less beyond (Cauchy loss), so a seam between surfaces that do not
  /// really meet gives up instead of turning their planes (m), > 0.
  double seam_give_up_m = 0.02;
  /// Faithfulness to the points' extent: the scale of a rectangle bound's
  /// move from the EM's fit (m), > 0.
  double extent_sigma_m = 0.05;
  /// false (default): rectangles keep the EM's in-plane orientation (only
  /// their planes and bounds move). true: they may turn in their plane,
  /// scale rotation_sigma_deg; measured worse on online maps, whose long
  /// rectangles then square up to a short seam and grow to hold their
  /// corner points (doc/refinement.md).
  bool free_rotation = false;
  /// Scale of a rectangle's in-plane rotation from the EM's fit (deg), > 0.
  double rotation_sigma_deg = 5.0;
  /// Huber loss of the measurements' in-plane residuals, in units of sigma, > 0.
  double robust_loss_sigmas = 3.0;
  /// Measurements near a rectangle's boundary (within seam_distance_m) whose
  /// in-plane residuals enter the solve: an even subsample of at most this
  /// many, weighted to stand for all of them (the plane residuals use every
  /// measurement through its moments), >= 10.
  int max_points_per_surface = 300;
  int max_iterations = 50;  ///< solver iterations, >= 1
  /// Manhattan prior (off by default): surfaces whose normals are within
  /// manhattan_tolerance_deg of parallel or orthogonal are snapped to it.
  bool manhattan = false;
  double manhattan_tolerance_deg = 2.0;  ///< in (0, 45)
  double manhattan_sigma_deg = 0.001;    ///< residual scale of the snap (deg), > 0
  /// Doors on openings (openings.h): a surface within this angle of a larger
  /// one, behind it by at most seam_distance_m and inside its rectangle, has
  /// its edges placed on the opening in that wall's points (deg), in (0, 90).
  bool openings = true;
  double opening_max_angle_deg = 10.0;
  /// A surface whose normal the solve would turn by more than this keeps the
  /// EM's geometry (a guard against a wrong seam; deg), > 0.
  double max_normal_change_deg = 2.0;

  bool validate(std::string* why) const;
};

}  // namespace pmap::refine
