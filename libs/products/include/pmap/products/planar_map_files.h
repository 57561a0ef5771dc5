// Files of the planar map (doc/outputs.md): surfaces.csv and the VRML97 map.
#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <vector>

#include "pmap/em/offline_em.h"
#include "pmap/products/vrml.h"

namespace pmap::products {

/// surfaces.csv: id, unit normal, offset (plane n . x = offset), the four
/// corners in order around the rectangle, support.
void writeSurfacesCsv(const std::filesystem::path& path, const std::vector<em::Surface>& surfaces);

/// The map as VRML meshes: one shape per rectangle (two triangles, coloured
/// by orientation: walls, ceilings/floors, slanted) and one for all fine
/// triangles.
std::vector<VrmlMesh> planarMapMeshes(const em::PlanarMap& map,
                                      const std::vector<Eigen::Vector3d>& points);

/// Per point the id of its surface (-1 = outlier class), for points.ply.
std::vector<int> surfaceIdsOfPoints(const em::PlanarMap& map);

}  // namespace pmap::products
