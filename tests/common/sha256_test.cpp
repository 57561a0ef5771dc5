#include "pmap/common/sha256.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>
#include <string>

#include "pmap/common/error.h"

namespace pmap {
namespace {
namespace fs = std::filesystem;

// FIPS 180-4 examples (NIST's SHA256.pdf) and the million-'a' vector.
TEST(Sha256, Item14_KnownVectors) {
  EXPECT_EQ(sha256Hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(sha256Hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(sha256Hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  EXPECT_EQ(sha256Hex(std::string(1000000, 'a')),
            "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

// Lengths around the padding boundaries (55 bytes is the last that pads
// within one block), checked against Python's hashlib.
TEST(Sha256, Item14_PaddingBoundaries) {
  const std::pair<std::size_t, const char*> cases[] = {
      {55, "d5e285683cd4efc02d021a5c62014694958901005d6f71e89e0989fac77e4072"},
      {56, "04c26261370ee7541549d16dee320c723e3fd14671e66a099afe0a377c16888e"},
      {63, "75220b47218278e656f2013bb8f0c455a25eaf01e86c64924e9d48d89776d6f2"},
      {64, "7ce100971f64e7001e8fe5a51973ecdfe1ced42befe7ee8d5fd6219506b5393c"},
      {65, "9537c5fdf120482f7d58d25e9ed583f52c02b4e304ea814db1633ad565aed7e9"},
      {119, "000b48d4edf0fa7bee3c6236ecd2785baa5db4eeb8bb54341b029e0d9fa5fb0c"},
      {120, "13f05a0b594787f5ecd315edc96141bd3243203d1b7d4f0836f37308b276ba98"}};
  for (const auto& [n, digest] : cases) {
    EXPECT_EQ(sha256Hex(std::string(n, 'x')), digest) << n << " bytes";
  }
}

TEST(Sha256, Item14_PiecewiseEqualsWholeAndResets) {
  std::string text;
  for (int i = 0; i < 1000; ++i) {
    text += std::to_string(i * 7919) + ",";
  }
  for (const std::size_t piece : {1u, 3u, 63u, 64u, 65u, 1000u}) {
    Sha256 sha;
    for (std::size_t i = 0; i < text.size(); i += piece) {
      sha.update(text.data() + i, std::min(piece, text.size() - i));
    }
    EXPECT_EQ(sha.hexDigest(), sha256Hex(text)) << piece;
    sha.update("abc", 3);  // hexDigest() reset it
    EXPECT_EQ(sha.hexDigest(), sha256Hex("abc"));
  }
}

TEST(Sha256, Item14_FileDigestAndMissingFile) {
  const fs::path dir = fs::path(PMAP_TEST_TMP_DIR) / ("sha256_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string bytes = std::string(200000, 'q') + std::string("\0\x01\xff", 3);
  std::ofstream(dir / "f.bin", std::ios::binary) << bytes;
  EXPECT_EQ(fileSha256(dir / "f.bin"), sha256Hex(bytes));
  try {
    fileSha256(dir / "missing.bin");
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("missing.bin"), std::string::npos) << e.what();
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace pmap
