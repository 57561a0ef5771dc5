// Test-side GLB parsing, independent of the writer's code.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace pmap::products::test {

struct GlbParts {
  std::uint32_t magic = 0, version = 0, length = 0;
  std::uint32_t json_chunk_length = 0, json_chunk_type = 0;
  std::uint32_t bin_chunk_length = 0, bin_chunk_type = 0;
  std::string json_text;  ///< with its padding
  nlohmann::json json;
  std::vector<std::uint8_t> bin;  ///< with its padding; empty without BIN chunk
};

inline std::uint32_t u32At(const std::vector<std::uint8_t>& b, std::size_t at) {
  return static_cast<std::uint32_t>(b.at(at)) | static_cast<std::uint32_t>(b.at(at + 1)) << 8 |
         static_cast<std::uint32_t>(b.at(at + 2)) << 16 |
         static_cast<std::uint32_t>(b.at(at + 3)) << 24;
}

inline GlbParts parseGlb(const std::vector<std::uint8_t>& b) {
  GlbParts p;
  p.magic = u32At(b, 0);
  p.version = u32At(b, 4);
  p.length = u32At(b, 8);
  p.json_chunk_length = u32At(b, 12);
  p.json_chunk_type = u32At(b, 16);
  p.json_text.assign(b.begin() + 20, b.begin() + 20 + p.json_chunk_length);
  p.json = nlohmann::json::parse(p.json_text);
  const std::size_t bin_at = 20 + p.json_chunk_length;
  if (bin_at < b.size()) {
    p.bin_chunk_length = u32At(b, bin_at);
    p.bin_chunk_type = u32At(b, bin_at + 4);
    p.bin.assign(b.begin() + bin_at + 8, b.begin() + bin_at + 8 + p.bin_chunk_length);
  }
  return p;
}

inline std::size_t componentSize(int component_type) {
  return component_type == 5126 || component_type == 5125 ? 4 : component_type == 5123 ? 2 : 1;
}

inline std::size_t componentCount(const std::string& type) {
  return type == "SCALAR" ? 1 : type == "VEC2" ? 2 : type == "VEC3" ? 3 : 4;
}

/// Absolute byte offset of an accessor's first element in the BIN chunk.
inline std::size_t accessorStart(const GlbParts& p, int accessor) {
  const auto& a = p.json["accessors"][accessor];
  const auto& v = p.json["bufferViews"][a["bufferView"].get<int>()];
  return v.value("byteOffset", std::size_t{0}) + a.value("byteOffset", std::size_t{0});
}

/// The FLOAT values of an accessor (tightly packed views only).
inline std::vector<float> floatsOf(const GlbParts& p, int accessor) {
  const auto& a = p.json["accessors"][accessor];
  EXPECT_EQ(a["componentType"], 5126);
  std::vector<float> out(a["count"].get<std::size_t>() * componentCount(a["type"]));
  std::memcpy(out.data(), p.bin.data() + accessorStart(p, accessor), out.size() * sizeof(float));
  return out;
}

/// The UNSIGNED_INT values of an accessor.
inline std::vector<std::uint32_t> uintsOf(const GlbParts& p, int accessor) {
  const auto& a = p.json["accessors"][accessor];
  EXPECT_EQ(a["componentType"], 5125);
  std::vector<std::uint32_t> out(a["count"].get<std::size_t>());
  std::memcpy(out.data(), p.bin.data() + accessorStart(p, accessor), out.size() * 4);
  return out;
}

}  // namespace pmap::products::test
