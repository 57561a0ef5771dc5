// Spatial blocks for the offline EM on large inputs (offline_em.h): the
// model is local (a measurement is explained by a surface a few sigma from
// it), so a building can be mapped in pieces whose work does not grow with
// the building. The points are cut by recursive median splits along the
// longer horizontal side of their bounding box until no piece holds more
// than a given number; each block also carries the points within a margin
// of its box (its neighbours' points), so that a surface cut by a seam is
// seen past it from both sides.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "pmap/em/neighbours.h"

namespace pmap::em {

struct SpatialBlock {
  /// Into the input: the block's own points first (`core` of them, in input
  /// order), then its margin's (in input order).
  std::vector<std::int32_t> index;
  std::size_t core = 0;
  Eigen::Vector2d lo = Eigen::Vector2d::Zero();  ///< x-y box of the own points
  Eigen::Vector2d hi = Eigen::Vector2d::Zero();
};

/// How many blocks cutIntoBlocks makes of `points` points (1 when they fit
/// in one): halving until a piece holds at most `max_points`, > 0.
std::size_t blockCount(std::size_t points, std::size_t max_points);

/// The blocks of `points` (finite): every point is in exactly one block's
/// own points; a block's margin holds the other points whose x and y lie
/// within `margin_m` (>= 0) of its box. Deterministic (ties by index).
std::vector<SpatialBlock> cutIntoBlocks(const std::vector<Eigen::Vector3d>& points,
                                        std::size_t max_points, double margin_m);

/// One block's measurements on their own: its points, their rows (empty
/// when `rows` is) and the neighbours among them (a neighbour outside the
/// block becomes -1).
struct BlockInput {
  std::vector<Eigen::Vector3d> points;
  std::vector<std::int32_t> rows;
  Neighbours neighbours;
};
BlockInput blockInput(const SpatialBlock& block, const std::vector<Eigen::Vector3d>& points,
                      const Neighbours& neighbours, const std::vector<std::int32_t>& rows);

}  // namespace pmap::em
