#include "pmap/products/texture_png.h"

#include <opencv2/imgcodecs.hpp>

#include "pmap/common/atomic_file.h"
#include "pmap/common/error.h"

namespace pmap::products {

std::string textureRelativePath(std::int32_t surface_id) {
  return OutputLayout::textureFile(surface_id);
}

std::string textureRelativePath(std::int32_t surface_id, std::int32_t tile) {
  return OutputLayout::textureFile(surface_id, tile);
}

std::vector<std::uint8_t> encodePng(const cv::Mat& image) {
  std::vector<std::uint8_t> png;
  bool ok = false;
  try {
    ok = !image.empty() && cv::imencode(".png", image, png);
  } catch (const cv::Exception& e) {
    throw OutputError(std::string("PNG encoding failed: ") + e.what());
  }
  if (!ok) {
    throw OutputError("PNG encoding failed (" + std::to_string(image.cols) + "x" +
                      std::to_string(image.rows) + " image, type " + std::to_string(image.type()) +
                      ")");
  }
  return png;
}

void writePngAtomically(const std::filesystem::path& png, const cv::Mat& image) {
  std::vector<std::uint8_t> bytes;
  try {
    bytes = encodePng(image);
  } catch (const OutputError& e) {
    throw OutputError(png.string() + ": " + e.what());
  }
  writeFileAtomically(
      png,
      [&](std::ostream& out) {
        out.write(reinterpret_cast<const char*>(bytes.data()),
                  static_cast<std::streamsize>(bytes.size()));
      },
      /*binary=*/true);
}

}  // namespace pmap::products
