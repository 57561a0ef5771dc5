// `planar-mapper --cloud FILE.ply`: a point cloud mapped directly, in its own
// (world) frame, as one unorganised structure "scan" with index 0.
#pragma once

#include <filesystem>

#include "pmap/input/structure_points.h"

namespace pmap::input {

/// Reads x, y, z of every vertex; non-finite points are dropped and counted.
/// Throws InputError for unreadable files or missing x/y/z properties.
StructureScan readPlyCloud(const std::filesystem::path& path);

}  // namespace pmap::input
