// textures.csv (doc/outputs.md): where each texture image lies in the world,
// so that tools (map-eval) can read the textures without parsing VRML or glTF.
#pragma once

#include <filesystem>

#include "pmap/products/map_model.h"

namespace pmap::products {

/// Writes `csv`: one line per textured quad with its image file (relative to
/// the csv: textures/surface_<id>_<tile>.png, written by writeMapVrml),
/// surface_id, tile, width_px, height_px, then the corners c0..c3 (x, y, z
/// each, m). Pixel (col, row) covers s in [col, col+1) / W along c0 -> c1
/// and t in [H-row-1, H-row) / H along c0 -> c3 (map_model.h). Atomic;
/// throws OutputError.
void writeTexturesCsv(const std::filesystem::path& csv, const MapModel& model);

}  // namespace pmap::products
