// SHA-256 (FIPS 180-4), for the manifests of output folders: each file is
// listed with its digest, so a reader can tell a file of the run from one
// left by another run or changed afterwards.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>

namespace pmap {

/// Incremental SHA-256: update() with the bytes in order, then hexDigest().
class Sha256 {
 public:
  Sha256() { reset(); }
  void reset();
  void update(const void* data, std::size_t size);
  /// The digest of everything given since reset(), as 64 lowercase hex
  /// digits; resets the object.
  std::string hexDigest();

 private:
  void compress(const std::uint8_t* block);

  std::array<std::uint32_t, 8> state_{};
  std::array<std::uint8_t, 64> buffer_{};
  std::size_t buffered_ = 0;
  std::uint64_t total_bytes_ = 0;
};

/// SHA-256 of `bytes` as 64 lowercase hex digits.
std::string sha256Hex(const std::string& bytes);

/// SHA-256 of a file's bytes. Throws InputError naming the file if it cannot
/// be opened or read.
std::string fileSha256(const std::filesystem::path& file);

}  // namespace pmap
