// The planar map as textured VRML97 (ISO/IEC 14772): map.wrl plus its
// textures/ folder (doc/outputs.md). The untextured writer for the raw map is
// vrml.h.
#pragma once

#include <filesystem>
#include <string>

#include "pmap/products/map_model.h"

namespace pmap::products {

/// Writes `model` as VRML97 to `wrl`:
///  - one Shape per rectangle: an IndexedFaceSet of two triangles (c0 c1 c2,
///    c0 c2 c3; solid FALSE, seen from both sides) with a TextureCoordinate
///    per the texture convention of map_model.h; a textured rectangle has an
///    ImageTexture { url "textures/surface_<id>_<tile>.png" } (lit by a white
///    Material), an untextured one a Material with its diffuseColor;
///  - one Shape for all fine triangles, with a Color node (colorPerVertex
///    TRUE) when per-vertex colours are given, else their diffuseColor.
/// Shapes are DEF-named surface_<id>_<tile> (id >= 0) and fine_triangles. The PNGs
/// are written into `textures/` beside `wrl` before the .wrl itself; every
/// file is written atomically. Throws OutputError when a file cannot be
/// written (a previous .wrl is then kept), std::invalid_argument when the
/// model breaks checkMapModel's rules. `comment` becomes a "# " line.
void writeMapVrml(const std::filesystem::path& wrl, const MapModel& model,
                  const std::string& comment = {});

}  // namespace pmap::products
