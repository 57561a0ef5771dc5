// Files of the planar map (doc/outputs.md): surfaces.csv and the points' surface ids.
#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <vector>

#include "pmap/em/offline_em.h"

namespace pmap::products {

/// surfaces.csv: id, unit normal, offset (plane n . x = offset), the four
/// corners in order around the rectangle, support.
void writeSurfacesCsv(const std::filesystem::path& path, const std::vector<em::Surface>& surfaces);

/// Per point the id of its surface (-1 = outlier class), for points.ply.
std::vector<int> surfaceIdsOfPoints(const em::PlanarMap& map);

}  // namespace pmap::products
