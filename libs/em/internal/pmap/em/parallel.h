// Deterministic parallel loops: work is cut into fixed-size chunks whatever
// the number of threads, each chunk's results are kept apart and combined in
// chunk order, so results do not depend on the thread count.
#pragma once

#include <algorithm>
#include <cstddef>
#include <functional>
#include <thread>
#include <vector>

namespace pmap::em {

constexpr std::size_t kChunkSize = 4096;

inline std::size_t chunkCount(std::size_t n) {
  return (n + kChunkSize - 1) / kChunkSize;
}

/// Calls fn(chunk, begin, end) for every chunk of [0, n), on up to `threads`
/// threads (chunks are handed out round-robin).
inline void forEachChunk(std::size_t n, int threads,
                         const std::function<void(std::size_t, std::size_t, std::size_t)>& fn) {
  const std::size_t chunks = chunkCount(n);
  const std::size_t t =
      std::min<std::size_t>(static_cast<std::size_t>(std::max(threads, 1)), chunks);
  auto worker = [&](std::size_t first) {
    for (std::size_t c = first; c < chunks; c += std::max<std::size_t>(t, 1)) {
      const std::size_t begin = c * kChunkSize;
      fn(c, begin, std::min(n, begin + kChunkSize));
    }
  };
  if (t <= 1) {
    worker(0);
    return;
  }
  std::vector<std::thread> pool;
  for (std::size_t k = 1; k < t; ++k) {
    pool.emplace_back(worker, k);
  }
  worker(0);
  for (auto& th : pool) {
    th.join();
  }
}

}  // namespace pmap::em
