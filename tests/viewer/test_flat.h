// Test support: a two-room flat (8 x 5 x 2.5 m, a wall with a door at x = 4)
// as planar-mapper maps it: em surfaces through products::buildMapModel (the
// normals turned towards the path) and encodeMapGlb, so the viewer tests see
// the exporter's real GLB (surface nodes with extras, the path line strip).
#pragma once

#include <cstdint>
#include <vector>

#include "pmap/products/map_model.h"

namespace pmap::viewer::testing {

/// Surface ids of the flat.
enum FlatSurface : std::int32_t {
  kFloor = 0,
  kCeiling = 1,
  kSouthWall = 2,       // y = 0
  kNorthWall = 3,       // y = 5, two tiles (as a textured run cuts long walls)
  kWestWall = 4,        // x = 0
  kEastWall = 5,        // x = 8
  kInnerWallSouth = 6,  // x = 4, y in [0, 2]
  kInnerWallNorth = 7,  // x = 4, y in [3, 5]
  kFlatSurfaces = 8
};

/// Points supporting surface `id` in the model.
inline std::int32_t flatSupport(std::int32_t id) {
  return 1000 + 37 * id;
}

/// The flat's model: 8 surfaces (9 quads), the path through the door.
products::MapModel flatModel();

/// The path's length (m).
double flatPathLength();

}  // namespace pmap::viewer::testing
