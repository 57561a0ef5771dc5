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

/// Writes the map files of `products` into `dir` (the staging folder) under
/// the names of products::OutputLayout; `folder_name` (--out's name) titles
/// viewer.html. Polls pmap::throwIfInterrupted() between files. Throws
/// OutputError.
void writeMapFiles(const std::filesystem::path& dir, const std::string& folder_name,
                   const MapProducts& products, const MappingResult& result,
                   const OutputOptions& options);

/// summary.json's "texture" block (doc/textures.md).
nlohmann::json textureSummary(const MapperConfig& config, const MapProducts& products);

/// Writes DIR/report/ (pictures and report.html) with the numbers of
/// `summary`; returns its warnings (a picture that could not be drawn).
std::vector<std::string> writeReportFiles(const std::filesystem::path& dir,
                                          const MapProducts& products, const MappingResult& result,
                                          const nlohmann::json& summary);

}  // namespace pmap::mapper
