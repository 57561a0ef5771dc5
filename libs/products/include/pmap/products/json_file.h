#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>

namespace pmap::products {

/// Writes `doc` pretty-printed (2 spaces) atomically; throws OutputError.
void writeJsonFile(const std::filesystem::path& path, const nlohmann::json& doc);

}  // namespace pmap::products
