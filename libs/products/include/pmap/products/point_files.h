// Files describing the measurements: points.ply and scans.csv
// (doc/outputs.md). map-eval and the OctoMap baseline read them back.
#pragma once

#include <filesystem>
#include <vector>

#include "pmap/points/point_map.h"

namespace pmap::products {

/// points.ply: binary little-endian; per vertex float x y z, int scan (the
/// structure scan index of gt.json), int beam, int surface (-1 = no surface).
/// `surface_ids` may be empty (all -1).
void writePointsPly(const std::filesystem::path& path, const points::PointMap& map,
                    const std::vector<int>& surface_ids);

/// scans.csv: one row per placed structure scan: index, timestamp, label,
/// sensor origin x y z and orientation as a unit quaternion qw qx qy qz (world
/// frame), robot pose x y yaw, number of points.
void writeScansCsv(const std::filesystem::path& path, const points::PointMap& map);

}  // namespace pmap::products
