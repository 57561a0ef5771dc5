// Beyond the paper: coverage cuts, the split test of a surface whose
// rectangle its points leave partly empty. A rectangle whose points cover an
// L (a ceiling continued around a corner) is cut in two; one stretched by a
// sparse appendage (a vertical scan that happened to lie in a wall's plane)
// is trimmed back; and two coplanar surfaces forming an L are brought into
// the canonical form (the larger runs through the corner). A proposal is
// only a partition; the selector fits the parts and keeps the change when it
// raises the log posterior (eq. 30).
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <vector>

#include "pmap/em/rectangle.h"
#include "pmap/em/split_proposals.h"

namespace pmap::em {

/// What a coverage cut keeps.
enum class CutKeep { kBoth, kPartA, kPartB };

struct CoverageCut {
  SplitProposal parts;
  CutKeep keep = CutKeep::kBoth;
  double estimated_gain = 0.0;  ///< from the grid estimate, before refitting
};

/// Coverage cut of `members` along one of the rectangle's axes, chosen on a
/// grid of `cell_m` for the largest estimated log-posterior gain: keeping
/// both parts saves empty area at the price of kappa; keeping one part (a
/// trim) saves more empty area at the price of the dropped points' loss
/// (`member_loss[k]`: how much worse member k is explained without this
/// surface, >= 0). Without `allow_trims` only cuts keeping both parts are
/// considered. None when no cut gains.
std::optional<CoverageCut> coverageCut(const std::vector<Eigen::Vector3d>& points,
                                       const std::vector<std::int32_t>& members,
                                       const std::vector<double>& member_loss,
                                       const Rectangle& rect, double cell_m, double empty_area_cost,
                                       double kappa, std::size_t min_part, bool allow_trims);

/// The canonical form of an L of two coplanar surfaces (a ceiling around a
/// corner): the members of the smaller surface (`other_members`, rectangle
/// `other`) that the larger one (`big`) takes so that it runs through the
/// corner: those within big's width at its end next to `other`. The width
/// comes from big's points `big_extent` within corner_end_window_m (1 m) of
/// that end (a rectangle turned by a fraction of a degree would narrow it
/// there), widened by `sigma`. Empty when they do not lie on big's plane
/// (fewer than corner_on_plane_percent (90 %) within grow_sigmas (2.5)
/// sigma: a door behind its wall is no L) or beyond its end (more than
/// corner_beside_percent (10 %) beside it: a room's ceiling next to a
/// corridor's is no L), or when `other` does not reach across big's axis at
/// least corner_min_leg_beyond_m (0.5 m) beyond its width (two collinear
/// pieces of one corridor are no L). The numbers: `rules`
/// (selection_rules.h).
std::vector<std::int32_t> cornerTransfer(const std::vector<Eigen::Vector3d>& points,
                                         const Rectangle& big,
                                         const std::vector<std::int32_t>& big_extent,
                                         const Rectangle& other,
                                         const std::vector<std::int32_t>& other_members,
                                         double sigma,
                                         const SelectionRules& rules = SelectionRules{});

}  // namespace pmap::em
