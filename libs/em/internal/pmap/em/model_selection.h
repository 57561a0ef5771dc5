// Model selection, eq. (30): log p(Theta | Z) = log p(Z | Theta) - kappa J
// - empty_area_cost * sum_j A_empty(j) + const. A change is made when it
// raises this log posterior.
//
// How the correspondence prior is handled when J is scored (MODEL.md): the
// uniform prior 1/(J+1) over causes is held fixed, i.e. log p(Z | Theta) is
// scored as sum_i log(exp(s*) + sum_j exp(s_ij)) without the -log(J+1) term.
// Keeping it would charge every new surface about N/(J+1) nats (N points),
// which swamps kappa and would forbid any surface in a large data set.
//
// The empty-area term (beyond the paper) is a prior against rectangle area
// that no measurement covers: without it an L-shaped ceiling is one rectangle
// over the L's bounding box, which explains the same points as two.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "pmap/em/measurement_model.h"
#include "pmap/em/planar_em_options.h"
#include "pmap/em/point_grid.h"
#include "pmap/em/responsibilities.h"
#include "pmap/em/surface.h"

namespace pmap::em {

/// Rectangle area (m^2) not covered by any of `members` on a grid of `cell_m`.
double emptyArea(const std::vector<Eigen::Vector3d>& points,
                 const std::vector<std::int32_t>& members, const Rectangle& rect, double cell_m);

/// Log posterior of the current map (the constant terms omitted).
double logPosterior(const Responsibilities& resp, const std::vector<Surface>& surfaces,
                    const std::vector<double>& empty_areas, const PlanarEmOptions& options);

/// A point's score from its terms: the mixture log-sum-exp (soft) or the
/// most likely cause's term (hard), see PlanarEmOptions::Scoring.
double combineScores(double a, double b, PlanarEmOptions::Scoring scoring);

/// The score of point i from its E-step entries (and the outlier term),
/// leaving out entry `skip_entry` (-1: none).
double pointScore(const Responsibilities& resp, std::size_t i, double s_star,
                  PlanarEmOptions::Scoring scoring, std::int64_t skip_entry = -1);

/// Change of the summed point scores when the surfaces `removed` are taken
/// out and the rectangles `added` put in, over the points `affected` (every
/// point whose terms change must be listed; ascending, no duplicates).
double logLikelihoodChange(const std::vector<Eigen::Vector3d>& points, const Responsibilities& resp,
                           const MeasurementModel& model, const std::vector<std::int32_t>& affected,
                           const std::vector<std::int32_t>& removed,
                           const std::vector<Rectangle>& added, double tolerance,
                           PlanarEmOptions::Scoring scoring);

/// Number of distinct values of rows[i] over `members` (0 if rows is empty).
std::size_t distinctRows(const std::vector<std::int32_t>& rows,
                         const std::vector<std::int32_t>& members);

/// Points whose terms a rectangle can change: within the cutoff of it.
std::vector<std::int32_t> pointsNear(const PointGrid& grid,
                                     const std::vector<Eigen::Vector3d>& points,
                                     const Rectangle& rect, double cutoff_m);

/// Sorted union of index lists.
std::vector<std::int32_t> unionOf(const std::vector<std::vector<std::int32_t>>& lists);

}  // namespace pmap::em
