#include "pmap/viewer/base64.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace pmap::viewer {
namespace {

std::string encode(const std::string& text) {
  return encodeBase64(reinterpret_cast<const std::uint8_t*>(text.data()), text.size());
}

std::vector<std::uint8_t> decode(const std::string& text) {
  const std::string alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::vector<std::uint8_t> out;
  std::uint32_t bits = 0;
  int count = 0;
  for (const char c : text) {
    if (c == '=') {
      break;
    }
    bits = (bits << 6) | std::uint32_t(alphabet.find(c));
    count += 6;
    if (count >= 8) {
      count -= 8;
      out.push_back(std::uint8_t(bits >> count));
    }
  }
  return out;
}

TEST(Base64, Rfc4648Vectors) {
  EXPECT_EQ(encode(""), "");
  EXPECT_EQ(encode("f"), "Zg==");
  EXPECT_EQ(encode("fo"), "Zm8=");
  EXPECT_EQ(encode("foo"), "Zm9v");
  EXPECT_EQ(encode("foob"), "Zm9vYg==");
  EXPECT_EQ(encode("fooba"), "Zm9vYmE=");
  EXPECT_EQ(encode("foobar"), "Zm9vYmFy");
}

TEST(Base64, EveryByteValueRoundTrips) {
  for (std::size_t size : {253u, 254u, 255u, 256u}) {
    std::vector<std::uint8_t> bytes(size);
    for (std::size_t i = 0; i < size; ++i) {
      bytes[i] = std::uint8_t(255 - i);
    }
    const std::string text = encodeBase64(bytes.data(), bytes.size());
    EXPECT_EQ(text.size() % 4, 0u);
    EXPECT_EQ(decode(text), bytes) << size;
  }
}

TEST(Base64, NullDataOfSizeZero) {
  EXPECT_EQ(encodeBase64(nullptr, 0), "");
}

}  // namespace
}  // namespace pmap::viewer
