// Helpers of the hostile-input tests: byte-level damage of files, the peak
// memory of the test process, and running a check without root's powers.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace pmap::testing {

using Bytes = std::vector<char>;

Bytes readFileBytes(const std::filesystem::path& path);
void writeFileBytes(const std::filesystem::path& path, const Bytes& bytes);

/// XORs `count` bytes at positions drawn from `seed` with non-zero values.
/// Deterministic on every platform (own generator, no std distributions).
void flipBytes(Bytes& bytes, std::uint32_t seed, int count);

/// Offsets of every little-endian uint32 equal to `value` in `bytes`.
std::vector<std::size_t> findUint32(const Bytes& bytes, std::uint32_t value);

/// Offsets of every occurrence of `text` in `bytes`.
std::vector<std::size_t> findText(const Bytes& bytes, const std::string& text);

/// Overwrites the little-endian uint32 at `offset`.
void putUint32(Bytes& bytes, std::size_t offset, std::uint32_t value);

/// Peak resident set size of this process so far (VmHWM), in MiB.
double peakRssMiB();

/// Runs `check` in a forked child that has dropped root's privileges
/// (uid/gid 65534, "nobody") when run as root, so that file permissions
/// hold. Returns the child's exit status (`check`'s return value), or -1 if
/// the child died from a signal or could not start.
int runUnprivileged(const std::function<int()>& check);

/// True when the process runs as root (chmod does not stop it).
bool runningAsRoot();

}  // namespace pmap::testing
