// M-step, eqs. (19)-(29): each surface's plane from the weighted centroid and
// the eigenvector of the smallest eigenvalue of the weighted scatter matrix
// (eqs. 24-27), then its rectangle: the smallest-area rectangle in the plane
// around the points most likely caused by it (eq. 29).
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "pmap/em/neighbours.h"
#include "pmap/em/responsibilities.h"
#include "pmap/em/selection_rules.h"
#include "pmap/em/surface.h"

namespace pmap::em {

/// Weighted first and second moments of points, about a reference point.
struct PlaneMoments {
  double weight = 0.0;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  Eigen::Matrix3d sum_sq = Eigen::Matrix3d::Zero();
  Eigen::Vector3d reference = Eigen::Vector3d::Zero();

  void add(const Eigen::Vector3d& p, double w);
  void merge(const PlaneMoments& o);  ///< same reference required
};

enum class FitStatus { kOk, kTooFewPoints, kDegenerate };

/// Plane from moments, eqs. (24)-(27): centroid z = sum / weight, normal =
/// eigenvector of the smallest eigenvalue of A = sum_sq - weight z z^T
/// (centred at the reference), oriented like `previous_normal`. Degenerate
/// when the two largest eigenvalues are not both clearly above the smallest
/// (a line or a point), judged by eigenvalue ratios.
FitStatus planeFromMoments(const PlaneMoments& m, const Eigen::Vector3d& previous_normal,
                           Rectangle& rect);

/// Eq. (29): the rectangle in rect's plane around `points` (exact minimum
/// area). Keeps the plane; sets centre, axis_u, half extents.
FitStatus fitRectangle(const std::vector<Eigen::Vector3d>& points,
                       const std::vector<std::int32_t>& members, Rectangle& rect);

/// fitRectangle that also returns the members on the rectangle's hull (a
/// small set that, kept, preserves the extent when the members are subsampled).
FitStatus fitRectangleWithHull(const std::vector<Eigen::Vector3d>& points,
                               const std::vector<std::int32_t>& members, Rectangle& rect,
                               std::vector<std::int32_t>& hull);

/// Plane and rectangle of a set of points with unit weights.
FitStatus fitSurface(const std::vector<Eigen::Vector3d>& points,
                     const std::vector<std::int32_t>& members, Rectangle& rect);

/// The M-step over all surfaces: planes from the soft weights of `resp`,
/// rectangles from the hard assignments (resp.best) that are spatially
/// coherent (see coherentMembers: at least `coherent_neighbours` of their
/// neighbours share their cause). Sets support. Surfaces whose fit fails
/// keep their previous geometry.
void maximizeSurfaces(const std::vector<Eigen::Vector3d>& points, const Neighbours& neighbours,
                      const Responsibilities& resp, int threads, std::vector<Surface>& surfaces,
                      int coherent_neighbours = SelectionRules{}.coherent_neighbours);

/// Beyond the paper: the members of surface j whose most likely cause is
/// shared by at least `min_same` of their neighbours. With a door recessed by
/// only two sigma, a few noisy wall points next to the opening are more
/// likely caused by the door; as rectangle corners they would stretch the
/// door over the wall (which then captures more wall points, iteration after
/// iteration). Isolated members still count in the plane fit, not in the
/// rectangle. Falls back to all members when too few remain.
std::vector<std::int32_t> coherentMembers(const std::vector<std::int32_t>& members,
                                          const Neighbours& neighbours,
                                          const std::vector<std::int32_t>& best, int min_same);

/// Points whose most likely cause is each surface, ascending.
std::vector<std::vector<std::int32_t>> hardMembers(const Responsibilities& resp,
                                                   std::size_t surfaces);

}  // namespace pmap::em
