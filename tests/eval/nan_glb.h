// A map GLB with one non-finite vertex coordinate, for the readers' input
// checks: `model` is encoded and the first float equal to `mark` (a value
// placed in one vertex for this purpose) becomes NaN in the bytes.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <vector>

#include "pmap/products/map_gltf.h"

namespace pmap::testing {

/// Writes the GLB to `path`; false if `mark` is not in the encoded bytes.
inline bool writeGlbWithNan(const products::MapModel& model, float mark,
                            const std::filesystem::path& path) {
  std::vector<std::uint8_t> bytes = products::encodeMapGlb(model, false);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const auto* m8 = reinterpret_cast<const std::uint8_t*>(&mark);
  const auto at = std::search(bytes.begin(), bytes.end(), m8, m8 + 4);
  if (at == bytes.end()) {
    return false;
  }
  std::memcpy(&*at, &nan, 4);
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char*>(bytes.data()),
             static_cast<std::streamsize>(bytes.size()));
  return true;
}

}  // namespace pmap::testing
