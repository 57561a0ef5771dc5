#include "pmap/texture/blend.h"

#include <atomic>
#include <thread>

namespace pmap::texture {

std::vector<VisibleTile> visibleTiles(const std::vector<TextureTile>& tiles,
                                      const CameraFrame& frame, double max_distance_m) {
  std::vector<VisibleTile> out;
  for (std::size_t i = 0; i < tiles.size(); ++i) {
    const TexelBox box = visibleTexels(tiles[i], frame, max_distance_m);
    if (!box.empty()) {
      out.push_back({i, box});
    }
  }
  return out;
}

void parallelFor(std::size_t n, int threads, const std::function<void(std::size_t)>& fn) {
  const std::size_t t = std::min<std::size_t>(static_cast<std::size_t>(std::max(1, threads)), n);
  if (t <= 1) {
    for (std::size_t i = 0; i < n; ++i) {
      fn(i);
    }
    return;
  }
  std::atomic<std::size_t> next{0};
  auto worker = [&] {
    for (std::size_t i = next++; i < n; i = next++) {
      fn(i);
    }
  };
  std::vector<std::thread> pool;
  for (std::size_t k = 1; k < t; ++k) {
    pool.emplace_back(worker);
  }
  worker();
  for (auto& th : pool) {
    th.join();
  }
}

std::size_t accumulateView(const FrameView& view, const std::vector<TextureTile>& tiles,
                           const std::vector<VisibleTile>& visible, const TextureOptions& options,
                           std::vector<cv::Mat>& acc) {
  const bool best = options.blend == "best";
  std::vector<std::size_t> counts(visible.size(), 0);
  parallelFor(visible.size(), options.threads, [&](std::size_t k) {
    const VisibleTile& v = visible[k];
    cv::Mat& a = acc[v.tile];
    if (a.empty()) {
      return;
    }
    std::size_t& count = counts[k];
    sampleTile(tiles[v.tile], v.box, view, options,
               [&a, &count, best](int col, int row, const cv::Vec3f& c, float w) {
                 ++count;
                 // Both keep (w * colour, w), so colour = sum / weight.
                 cv::Vec4f& t = a.at<cv::Vec4f>(row, col);
                 const cv::Vec4f s(w * c[0], w * c[1], w * c[2], w);
                 if (!best) {
                   t += s;
                 } else if (w > t[3]) {
                   t = s;
                 }
               });
  });
  std::size_t total = 0;
  for (std::size_t c : counts) {
    total += c;
  }
  return total;
}

}  // namespace pmap::texture
