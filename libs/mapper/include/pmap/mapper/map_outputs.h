// The map products planar-mapper writes (doc/outputs.md): map.wrl (+
// textures/), map.glb, textures.csv, frames.csv, viewer.html, map.3Dscene
// and report/.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "pmap/mapper/map_products.h"
#include "pmap/mapper/mapper_config.h"
#include "pmap/mapper/pipeline.h"

namespace pmap::mapper {

/// Writes the map files of `products` into `out`. Throws OutputError.
void writeMapFiles(const std::filesystem::path& out, const MapProducts& products,
                   const MappingResult& result, const OutputOptions& options);

/// summary.json's "texture" block (doc/textures.md).
nlohmann::json textureSummary(const MapperConfig& config, const MapProducts& products);

/// Writes out/report/ (pictures and report.html) with the numbers of
/// `summary`; returns its warnings (a picture that could not be drawn).
std::vector<std::string> writeReportFiles(const std::filesystem::path& out,
                                          const MapProducts& products, const MappingResult& result,
                                          const nlohmann::json& summary);

}  // namespace pmap::mapper
