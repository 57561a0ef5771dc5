// The reference surfaces of the surface evaluation: ground-truth rectangles
// the laser saw often enough (eligible), each clipped to the extent of the
// mapped points labelled with it (what the laser saw of it).
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <unordered_map>
#include <vector>

#include "pmap/eval/ground_truth.h"

namespace pmap::eval {

using Rectangle = std::array<Eigen::Vector3d, 4>;

struct ReferenceSurface {
  GtRectangle rect;        ///< the ground-truth surface
  std::size_t hits = 0;    ///< beams of gt.json's structure scans that hit it
  std::size_t points = 0;  ///< mapped points labelled with it
  Rectangle clipped;       ///< rect clipped to its points' extent (rect if no points)
};

/// Eligible surfaces, sorted by id: ground-truth rectangles (never clutter)
/// with at least `min_hits` hits. `points` are the mapped points in the
/// ground-truth frame, `labels` their ground-truth labels (pointLabels).
std::vector<ReferenceSurface> referenceSurfaces(const GroundTruth& gt,
                                                const std::unordered_map<int, std::size_t>& hits,
                                                const std::vector<Eigen::Vector3d>& points,
                                                const std::vector<int>& labels,
                                                std::size_t min_hits);

/// The rectangle clipped to the bounding box of `points` projected into its
/// own 2D frame (origin c0, axes along c0->c1 and c0->c3); corners keep the
/// rectangle's order. No points: the rectangle itself.
Rectangle clipToPoints(const Rectangle& rect, const std::vector<Eigen::Vector3d>& points);

}  // namespace pmap::eval
