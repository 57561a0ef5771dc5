#include "pmap/products/glb_container.h"

#include <gtest/gtest.h>

#include "glb_reader.h"

namespace pmap::products {
namespace {

TEST(GlbContainer, HeaderAndJsonChunkWithoutBin) {
  const auto glb = packGlb("{}", {});
  ASSERT_EQ(glb.size(), 12u + 8u + 4u);
  const auto p = test::parseGlb(glb);
  EXPECT_EQ(p.magic, kGlbMagic);
  EXPECT_EQ(std::string(glb.begin(), glb.begin() + 4), "glTF");
  EXPECT_EQ(p.version, 2u);
  EXPECT_EQ(p.length, glb.size());
  EXPECT_EQ(p.json_chunk_type, kGlbChunkJson);
  EXPECT_EQ(std::string(glb.begin() + 16, glb.begin() + 20), "JSON");
  EXPECT_EQ(p.json_text, "{}  ");  // padded with spaces
  EXPECT_TRUE(p.bin.empty());
}

TEST(GlbContainer, BinChunkPaddedWithZeros) {
  const auto glb = packGlb("{\"a\":1}", {1, 2, 3, 4, 5});
  const auto p = test::parseGlb(glb);
  EXPECT_EQ(p.json_chunk_length, 8u);
  EXPECT_EQ(p.json_text, "{\"a\":1} ");
  EXPECT_EQ(p.bin_chunk_type, kGlbChunkBin);
  EXPECT_EQ(std::string(glb.begin() + 32, glb.begin() + 35), "BIN");
  EXPECT_EQ(glb[35], 0);
  EXPECT_EQ(p.bin, (std::vector<std::uint8_t>{1, 2, 3, 4, 5, 0, 0, 0}));
  EXPECT_EQ(p.length, glb.size());
}

TEST(GlbContainer, EveryChunkIsFourByteAligned) {
  for (std::size_t json_size = 1; json_size <= 9; ++json_size) {
    for (std::size_t bin_size = 0; bin_size <= 9; ++bin_size) {
      const auto glb =
          packGlb('"' + std::string(json_size, 'a') + '"', std::vector<std::uint8_t>(bin_size, 7));
      const auto p = test::parseGlb(glb);
      EXPECT_EQ(glb.size() % 4, 0u);
      EXPECT_EQ(p.length, glb.size());
      EXPECT_EQ(p.json_chunk_length % 4, 0u);
      EXPECT_LT(p.json_chunk_length - json_size - 2, 4u);
      EXPECT_EQ(p.bin_chunk_length % 4, 0u);
      EXPECT_LT(p.bin_chunk_length - bin_size, 4u);
    }
  }
}

}  // namespace
}  // namespace pmap::products
