// Shared by the libFuzzer targets and their replay in the ordinary build.
#pragma once

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace pmap::fuzz {

/// A scratch file of this process (parallel fuzzing jobs do not collide).
inline std::filesystem::path scratchFile(const char* name) {
  const char* tmp = std::getenv("TMPDIR");
  return std::filesystem::path(tmp != nullptr ? tmp : "/tmp") /
         ("pmap-fuzz-" + std::to_string(::getpid()) + "-" + name);
}

inline void writeScratch(const std::filesystem::path& path, const std::uint8_t* data,
                         std::size_t size) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
}

/// A broken invariant: report and abort, so the fuzzer keeps the input.
[[noreturn]] inline void invariantFailed(const char* what) {
  std::fprintf(stderr, "fuzz invariant failed: %s\n", what);
  std::abort();
}

}  // namespace pmap::fuzz
