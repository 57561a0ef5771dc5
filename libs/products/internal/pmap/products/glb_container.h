// The glTF 2.0 binary container (GLB, glTF 2.0 spec section 4.4): a 12-byte
// header, a JSON chunk and an optional BIN chunk.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace pmap::products {

inline constexpr std::uint32_t kGlbMagic = 0x46546C67;      ///< "glTF"
inline constexpr std::uint32_t kGlbChunkJson = 0x4E4F534A;  ///< "JSON"
inline constexpr std::uint32_t kGlbChunkBin = 0x004E4942;   ///< "BIN\0"

/// The GLB bytes (little-endian): header (magic, version 2, total length),
/// the JSON chunk padded with spaces to a multiple of 4 bytes, then the BIN
/// chunk padded with zeros to a multiple of 4 bytes (left out when `bin` is
/// empty). Throws OutputError beyond 4 GiB. The JSON's buffers[0].byteLength must be bin.size()
/// (unpadded).
std::vector<std::uint8_t> packGlb(const std::string& json, const std::vector<std::uint8_t>& bin);

}  // namespace pmap::products
