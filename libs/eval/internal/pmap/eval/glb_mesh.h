// The triangles of a glTF 2.0 binary file (map.glb, map-geometry.glb,
// raw.glb; doc/outputs.md): map-eval reads the maps' geometry from the files.
#pragma once

#include <filesystem>
#include <vector>

#include "pmap/eval/triangle_index.h"

namespace pmap::eval {

/// Every triangle of every mesh primitive (mode TRIANGLES, the default):
/// POSITION as FLOAT VEC3 (any byteStride), indices UNSIGNED_INT, SHORT or
/// BYTE or none. Positions are taken as stored (the mapper's files hold
/// world coordinates in the accessors and put the z-up to y-up turn on the
/// root node), so node transforms are not applied. Throws InputError naming
/// the file for a malformed file or an unsupported layout.
std::vector<Triangle3> readGlbTriangles(const std::filesystem::path& glb);

}  // namespace pmap::eval
