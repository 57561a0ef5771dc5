// Texture images of the map's rectangles as PNG (doc/outputs.md, "textures/").
#pragma once

#include <cstdint>
#include <filesystem>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "pmap/products/output_layout.h"

namespace pmap::products {

/// Folder of the texture files, relative to the map file that uses them.
inline constexpr const char* kTextureDir = OutputLayout::kTexturesDir;

/// "textures/surface_<id>.png" (OutputLayout::textureFile): the texture of
/// surface `surface_id`, relative to the map file (also the URL written into
/// map.wrl).
std::string textureRelativePath(std::int32_t surface_id);

/// "textures/surface_<id>_<tile>.png": tile `tile` of surface `surface_id`.
std::string textureRelativePath(std::int32_t surface_id, std::int32_t tile);

/// PNG bytes of an 8-bit BGR (or grey) image; throws OutputError if OpenCV
/// cannot encode it.
std::vector<std::uint8_t> encodePng(const cv::Mat& image);

/// Writes `image` as a PNG file, atomically; throws OutputError.
void writePngAtomically(const std::filesystem::path& png, const cv::Mat& image);

}  // namespace pmap::products
