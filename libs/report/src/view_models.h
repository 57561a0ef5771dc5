// Copies of the map model prepared for the report's views.
#pragma once

#include <Eigen/Core>

#include "pmap/products/map_model.h"

namespace pmap::report::detail {

/// The model without ceilings: rectangles with |n_z| > 0.7 whose centre, and
/// fine triangles whose centroid, lie more than `cut_m` above `floor_z`.
products::MapModel withoutCeilings(const products::MapModel& model, double floor_z, double cut_m);

/// Adds flat horizontal strips `width_m` wide to the fine triangles, for the
/// top view: one on top of every steep rectangle (|n_z| <= 0.7) along its
/// horizontal extent, in its colour (a texture's mean colour) darkened to 60 %, and along the
/// path (0.1 m above it) in `path_rgb`. The path itself is cleared.
void addFootprints(products::MapModel& model, double width_m, const Eigen::Vector3d& path_rgb);

}  // namespace pmap::report::detail
