#include "pmap/products/glb_container.h"

#include <string>

#include "pmap/common/error.h"

namespace pmap::products {
namespace {

std::size_t padded4(std::size_t n) {
  return (n + 3) / 4 * 4;
}

void putU32(std::vector<std::uint8_t>& out, std::uint32_t v) {
  for (int shift = 0; shift < 32; shift += 8) {
    out.push_back(static_cast<std::uint8_t>((v >> shift) & 0xFF));
  }
}

void putChunk(std::vector<std::uint8_t>& out, std::uint32_t type, const std::uint8_t* data,
              std::size_t size, std::uint8_t pad) {
  putU32(out, static_cast<std::uint32_t>(padded4(size)));
  putU32(out, type);
  out.insert(out.end(), data, data + size);
  out.insert(out.end(), padded4(size) - size, pad);
}

}  // namespace

std::vector<std::uint8_t> packGlb(const std::string& json, const std::vector<std::uint8_t>& bin) {
  const std::size_t total =
      12 + 8 + padded4(json.size()) + (bin.empty() ? 0 : 8 + padded4(bin.size()));
  if (total > 0xFFFFFFFFull) {
    throw OutputError("GLB would exceed 4 GiB (" + std::to_string(total) + " bytes)");
  }
  std::vector<std::uint8_t> out;
  out.reserve(total);
  putU32(out, kGlbMagic);
  putU32(out, 2);
  putU32(out, static_cast<std::uint32_t>(total));
  putChunk(out, kGlbChunkJson, reinterpret_cast<const std::uint8_t*>(json.data()), json.size(),
           ' ');
  if (!bin.empty()) {
    putChunk(out, kGlbChunkBin, bin.data(), bin.size(), 0);
  }
  return out;
}

}  // namespace pmap::products
