// The mapper's surfaces.csv (doc/evaluation.md): one rectangle per map
// surface, read strictly. Evaluation reads the file, not the mapper.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <filesystem>
#include <vector>

#include "pmap/eval/map_files.h"
#include "pmap/eval/pose_metrics.h"

namespace pmap::eval {

/// One row of surfaces.csv: the plane n . x = offset_m and its rectangle.
struct MapSurface {
  int id = -1;                                        ///< as in points.ply's `surface`
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  ///< unit normal
  double offset_m = 0;                                ///< plane offset along the normal
  std::array<Eigen::Vector3d, 4> corners;             ///< in order around the rectangle
  std::int64_t support = 0;                           ///< points the mapper assigned to it
};

/// The header line surfaces.csv must start with.
extern const char* const kSurfacesCsvHeader;

/// Reads DIR/surfaces.csv: exact header, 18 columns, finite numbers, id >= 0
/// and unique, support >= 0, |normal| within 1e-3 of 1 (then normalised, the
/// offset with it). Throws InputError naming the file and line.
std::vector<MapSurface> readMapSurfaces(const std::filesystem::path& csv);

/// Every point's surface id is -1 or an id of `surfaces`; otherwise throws
/// InputError naming `ply` and the first offending vertex.
void checkSurfaceIds(const MapPoints& points, const std::vector<MapSurface>& surfaces,
                     const std::filesystem::path& ply);

/// The surface moved by the rigid motion (corners, normal and offset).
MapSurface movedSurface(const MapSurface& s, const Rigid2D& motion);

}  // namespace pmap::eval
