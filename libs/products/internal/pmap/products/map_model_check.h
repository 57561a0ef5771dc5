// Preconditions the map exporters (map_vrml.h, map_gltf.h) rely on.
#pragma once

#include "pmap/products/map_model.h"

namespace pmap::products {

/// Checks that `model` can be exported; throws std::invalid_argument naming
/// the violated rule (a caller bug, not a data outcome):
///  - every corner, normal, colour, vertex and path position is finite,
///    normals non-zero;
///  - (surface_id, tile) is unique among the quads with surface_id >= 0;
///  - a textured quad has surface_id >= 0 and tile >= 0 (they name its
///    texture file) and a CV_8UC3 (BGR) texture;
///  - fine triangle indices are < vertices.size();
///  - fine colours are empty or one per vertex.
void checkMapModel(const MapModel& model);

}  // namespace pmap::products
