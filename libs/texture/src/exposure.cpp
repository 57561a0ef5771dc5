#include "pmap/texture/exposure.h"

#include <algorithm>

#include "pmap/texture/blend.h"
#include "pmap/texture/luminance.h"

namespace pmap::texture {
namespace {

constexpr int kRounds = 3;
constexpr std::size_t kMinOverlapTexels = 20;
constexpr float kDarkest = 12.f, kBrightest = 243.f;  // unreliable ratios outside

float median(std::vector<float> v) {
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

struct Views {
  std::vector<std::vector<VisibleTile>> visible;
  std::vector<DepthBuffer> depth;
};

Views prepare(const std::vector<TextureTile>& tiles, const std::vector<CameraFrame>& frames,
              const std::vector<cv::Mat>& images, const TextureOptions& options) {
  Views v;
  const products::ColoredTriangles none;
  for (std::size_t f = 0; f < frames.size(); ++f) {
    v.visible.push_back(images[f].empty() ? std::vector<VisibleTile>{}
                                          : visibleTiles(tiles, frames[f], options.max_distance_m));
    v.depth.emplace_back(frames[f], v.visible.back().empty() ? std::vector<TextureTile>{} : tiles,
                         none, 1);
  }
  return v;
}

FrameView viewOf(const Views& v, std::size_t f, const std::vector<CameraFrame>& frames,
                 const std::vector<cv::Mat>& images, const std::vector<double>& weights, float gain,
                 const TextureOptions& options) {
  return FrameView(frames[f], images[f], &v.depth[f], gain, weights[f], options);
}

// The median ratio of the others' reference to this frame's own colours.
float frameRatio(const FrameView& view, const std::vector<TextureTile>& tiles,
                 const std::vector<VisibleTile>& visible, const std::vector<cv::Mat>& acc,
                 const TextureOptions& options, std::size_t& overlap) {
  std::vector<float> ratios;
  for (const VisibleTile& vt : visible) {
    const cv::Mat& a = acc[vt.tile];
    sampleTile(tiles[vt.tile], vt.box, view, options,
               [&](int col, int row, const cv::Vec3f& c, float w) {
                 const cv::Vec4f& t = a.at<cv::Vec4f>(row, col);
                 const float others_w = t[3] - w;
                 if (others_w <= 1e-3f * t[3]) {
                   return;
                 }
                 // c carries the current gain, as the frame's own share of t.
                 const cv::Vec3f ref((t[0] - w * c[0]) / others_w, (t[1] - w * c[1]) / others_w,
                                     (t[2] - w * c[2]) / others_w);
                 const float raw = luminance(c) / view.gain;
                 if (raw > kDarkest && raw < kBrightest && luminance(ref) > kDarkest) {
                   ratios.push_back(luminance(ref) / raw);
                 }
               });
  }
  overlap = ratios.size();
  return ratios.size() >= kMinOverlapTexels ? median(ratios) : 0.f;
}

}  // namespace

ExposureResult estimateGains(const std::vector<TextureTile>& tiles,
                             const std::vector<CameraFrame>& frames,
                             const std::vector<cv::Mat>& images,
                             const std::vector<double>& frame_weights,
                             const TextureOptions& options) {
  ExposureResult r;
  r.gains.assign(frames.size(), 1.f);
  const Views views = prepare(tiles, frames, images, options);
  TextureOptions weighted = options;
  weighted.blend = "weighted";
  weighted.threads = 1;
  for (int round = 0; round < kRounds; ++round) {
    std::vector<cv::Mat> acc;
    for (const TextureTile& t : tiles) {
      acc.emplace_back(t.height, t.width, CV_32FC4, cv::Scalar::all(0));
    }
    for (std::size_t f = 0; f < frames.size(); ++f) {
      accumulateView(viewOf(views, f, frames, images, frame_weights, r.gains[f], options), tiles,
                     views.visible[f], weighted, acc);
    }
    std::vector<float> next(frames.size(), 0.f);
    parallelFor(frames.size(), options.threads, [&](std::size_t f) {
      std::size_t overlap = 0;
      next[f] = frameRatio(viewOf(views, f, frames, images, frame_weights, r.gains[f], options),
                           tiles, views.visible[f], acc, weighted, overlap);
    });
    std::vector<float> valid;
    for (float g : next) {
      if (g > 0) {
        valid.push_back(g);
      }
    }
    r.frames_with_overlap = valid.size();
    r.rounds = round + 1;
    if (valid.empty()) {
      break;
    }
    const float norm = median(valid);
    for (std::size_t f = 0; f < frames.size(); ++f) {
      r.gains[f] = next[f] > 0 ? std::clamp(next[f] / norm, 0.25f, 4.f) : 1.f;
    }
  }
  return r;
}

}  // namespace pmap::texture
