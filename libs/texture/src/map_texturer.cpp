#include "pmap/texture/map_texturer.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "pmap/common/error.h"
#include "pmap/texture/blend.h"
#include "pmap/texture/detail_transfer.h"
#include "pmap/texture/exposure.h"
#include "pmap/texture/hole_fill.h"
#include "pmap/texture/luminance.h"

namespace pmap::texture {
namespace {

constexpr double kThumbScale = 0.125;  // thumbnails for exposure estimation
constexpr double kCoarsePpm = 20.0;    // texels per metre of the exposure tiles
constexpr int kDepthCellPx = 4;        // occlusion buffer cell (image pixels)

struct Frames {
  std::vector<CameraFrame> full;   ///< fitted to the decoded image size
  std::vector<CameraFrame> thumb;  ///< the same at kThumbScale
  std::vector<cv::Mat> thumbs;     ///< empty: frame unused
  std::vector<std::vector<VisibleTile>> visible;
  std::vector<char> sees_fine;
};

// The frame for an image of a different size than its calibration (the
// intrinsics scale with the image, as MRPT's TCamera::scaleToResolution).
CameraFrame fitToImage(const CameraFrame& f, const cv::Mat& img) {
  if (f.width == img.cols && f.height == img.rows) {
    return f;
  }
  if (f.width <= 0 || f.height <= 0 ||
      std::abs(static_cast<double>(img.cols) / f.width - static_cast<double>(img.rows) / f.height) >
          0.01) {
    throw InputError("image of " + f.label + " at t=" + std::to_string(f.timestamp) + " is " +
                     std::to_string(img.cols) + "x" + std::to_string(img.rows) +
                     " but its calibration is " + std::to_string(f.width) + "x" +
                     std::to_string(f.height));
  }
  CameraFrame g = f.scaled(static_cast<double>(img.cols) / f.width);
  g.scale = 1.0;
  return g;
}

bool seesAnyVertex(const CameraFrame& f, const products::ColoredTriangles& fine, double max_d) {
  for (const Eigen::Vector3d& v : fine.vertices) {
    if ((v - f.centre).norm() < max_d && f.project(v)) {
      const auto px = f.project(v);
      if (px->x() >= 0 && px->y() >= 0 && px->x() <= f.width - 1 && px->y() <= f.height - 1) {
        return true;
      }
    }
  }
  return false;
}

// First read of every frame: size, thumbnail, what it sees.
Frames prepareFrames(const std::vector<TextureTile>& tiles, const products::ColoredTriangles& fine,
                     const std::vector<CameraFrame>& frames, const ImageLoader& load,
                     const TextureOptions& options, TextureResult& result) {
  Frames fr;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    fr.full.push_back(frames[i]);
    fr.visible.push_back(visibleTiles(tiles, frames[i], options.max_distance_m));
    fr.sees_fine.push_back(seesAnyVertex(frames[i], fine, options.max_distance_m));
    fr.thumbs.emplace_back();
    if (fr.visible.back().empty() && !fr.sees_fine.back()) {
      fr.thumb.push_back(frames[i].scaled(kThumbScale));
      continue;
    }
    const cv::Mat img = load(frames[i]);
    ++result.image_reads;
    fr.full.back() = fitToImage(frames[i], img);
    fr.thumb.push_back(fr.full.back().scaled(kThumbScale));
    cv::resize(img, fr.thumbs.back(), cv::Size(fr.thumb.back().width, fr.thumb.back().height), 0, 0,
               cv::INTER_AREA);
  }
  return fr;
}

// Tiles in groups whose accumulators fit the memory budget.
std::vector<std::vector<std::size_t>> groupTiles(const std::vector<TextureTile>& tiles,
                                                 double budget_mb, double bytes_per_texel) {
  std::vector<std::vector<std::size_t>> groups(1);
  double used = 0;
  for (std::size_t i = 0; i < tiles.size(); ++i) {
    const double mb = bytes_per_texel * tiles[i].width * tiles[i].height / 1e6;
    if (!groups.back().empty() && used + mb > budget_mb) {
      groups.emplace_back();
      used = 0;
    }
    groups.back().push_back(i);
    used += mb;
  }
  return groups;
}

std::size_t colourVertices(const FrameView& view, const products::ColoredTriangles& fine,
                           const TextureOptions& options, std::vector<cv::Vec4f>& acc) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < fine.vertices.size(); ++i) {
    cv::Vec3f c;
    const Eigen::Vector3d cam = view.frame->world_to_camera * fine.vertices[i];
    const double w =
        sampleView(cam, Eigen::Vector3d::Zero(), DepthBuffer::kFineTriangles, view, options, c);
    if (w > 0) {
      acc[i] += cv::Vec4f(static_cast<float>(w) * c[0], static_cast<float>(w) * c[1],
                          static_cast<float>(w) * c[2], static_cast<float>(w));
      ++n;
    }
  }
  return n;
}

void setVertexColours(const std::vector<cv::Vec4f>& acc, products::ColoredTriangles& fine,
                      TextureResult& result) {
  fine.colors.assign(fine.vertices.size(), fine.color.cast<float>());
  for (std::size_t i = 0; i < acc.size(); ++i) {
    if (acc[i][3] > 0) {  // BGR sums -> RGB in [0, 1]
      fine.colors[i] = Eigen::Vector3f(acc[i][2], acc[i][1], acc[i][0]) / (255.f * acc[i][3]);
      ++result.fine_vertices_seen;
    }
  }
  if (result.fine_vertices_seen == 0) {
    fine.colors.clear();
  }
}

// The finished texture of a tile; empty when no frame saw it.
products::TexturedQuad resolveTile(const TextureTile& tile, const cv::Mat& acc,
                                   const products::TexturedQuad& source, long long& seen) {
  products::TexturedQuad q = tile.quad();
  q.color = source.color;
  cv::Vec4d sum(0, 0, 0, 0);
  long long n = 0;
  for (int r = 0; r < acc.rows; ++r) {
    const auto* p = acc.ptr<cv::Vec4f>(r);
    for (int c = 0; c < acc.cols; ++c) {
      if (p[c][3] > 0) {
        sum += cv::Vec4d(p[c][0] / p[c][3], p[c][1] / p[c][3], p[c][2] / p[c][3], 1.0);
        ++n;
      }
    }
  }
  seen += n;
  if (n > 0) {
    const cv::Vec3f mean(static_cast<float>(sum[0] / n), static_cast<float>(sum[1] / n),
                         static_cast<float>(sum[2] / n));
    q.texture = resolveTexture(acc, mean);
    q.color = Eigen::Vector3d(mean[2], mean[1], mean[0]) / 255.0;
  }
  return q;
}

// One run of textureMap: the passes over the frames, group by group.
class Texturer {
 public:
  Texturer(products::MapModel& model, const std::vector<CameraFrame>& frames,
           const ImageLoader& load, const TextureOptions& options, TextureResult& result)
      : model_(model), frames_(frames), load_(load), options_(options), result_(result) {}

  void run() {
    tiles_ = planTiles(model_.quads, options_);
    result_.frames = frames_.size();
    result_.tiles = tiles_.size();
    result_.pixels_per_m =
        tiles_.empty() ? options_.pixels_per_m : tiles_[0].width / tiles_[0].length_u;
    fr_ = prepareFrames(tiles_, model_.fine, frames_, load_, options_, result_);
    estimateExposure();
    result_.detail_slope.assign(frames_.size(), -1.0);
    used_.assign(frames_.size(), 0);
    fine_acc_.assign(model_.fine.vertices.size(), cv::Vec4f(0, 0, 0, 0));
    std::vector<products::TexturedQuad> out(tiles_.size());
    const bool weigh_detail = options_.sharpness_power > 0;
    const auto groups = groupTiles(tiles_, options_.memory_budget_mb, weigh_detail ? 32.0 : 16.0);
    result_.groups = groups.size();
    for (std::size_t g = 0; g < groups.size(); ++g) {
      std::vector<cv::Mat> reference;
      if (weigh_detail) {
        reference = accumulators(groups[g]);
        pass(g, nullptr, reference);
      }
      std::vector<cv::Mat> acc = accumulators(groups[g]);
      pass(g, weigh_detail ? &reference : nullptr, acc);
      for (std::size_t i : groups[g]) {
        out[i] = resolveTile(tiles_[i], acc[i], sourceQuad(tiles_[i]), seen_);
        result_.textured_tiles += out[i].texture.empty() ? 0 : 1;
        result_.texels += 1LL * tiles_[i].width * tiles_[i].height;
      }
    }
    model_.quads = std::move(out);
    finish();
  }

 private:
  void estimateExposure() {
    result_.gains.assign(frames_.size(), 1.f);
    if (!options_.exposure_compensation) {
      return;
    }
    TextureOptions coarse = options_;
    coarse.pixels_per_m = std::min(options_.pixels_per_m, kCoarsePpm);
    const std::vector<double> ones(frames_.size(), 1.0);
    result_.gains =
        estimateGains(planTiles(model_.quads, coarse), fr_.thumb, fr_.thumbs, ones, options_).gains;
  }

  std::vector<cv::Mat> accumulators(const std::vector<std::size_t>& group) const {
    std::vector<cv::Mat> acc(tiles_.size());
    for (std::size_t i : group) {
      acc[i] = cv::Mat(tiles_[i].height, tiles_[i].width, CV_32FC4, cv::Scalar::all(0));
    }
    return acc;
  }

  // One pass over the frames that see the group: with `reference`, each
  // view is first weighed by how much of its detail survives (the final
  // pass); the first group's final pass also colours the fine triangles.
  void pass(std::size_t g, const std::vector<cv::Mat>* reference, std::vector<cv::Mat>& acc) {
    const bool final_pass = reference != nullptr || options_.sharpness_power <= 0;
    for (std::size_t f = 0; f < frames_.size(); ++f) {
      const bool fine_here = final_pass && g == 0 && fr_.sees_fine[f];
      const bool tiles_here =
          std::any_of(fr_.visible[f].begin(), fr_.visible[f].end(),
                      [&](const VisibleTile& v) { return !acc[v.tile].empty(); });
      if (!fine_here && !tiles_here) {
        continue;
      }
      const cv::Mat img = load_(frames_[f]);
      ++result_.image_reads;
      const DepthBuffer depth(fr_.full[f], tiles_, model_.fine, kDepthCellPx);
      FrameView view(fr_.full[f], img, &depth, result_.gains[f], 1.0, options_);
      if (reference != nullptr) {
        view.frame_weight = detailWeight(f, view, *reference);
      }
      if (accumulateView(view, tiles_, fr_.visible[f], options_, acc) > 0 && final_pass) {
        used_[f] = 1;
      }
      if (fine_here && colourVertices(view, model_.fine, options_, fine_acc_) > 0) {
        used_[f] = 1;
      }
    }
  }

  // weight = clamp(slope, 0.05, 2)^sharpness_power (detail_transfer.h); 1
  // when the frame shows too little detail to tell. A frame registered in
  // an earlier group keeps its slope.
  double detailWeight(std::size_t f, const FrameView& view, const std::vector<cv::Mat>& reference) {
    if (result_.detail_slope[f] < 0) {
      const auto slope =
          detailSlope(measureDetail(view, tiles_, fr_.visible[f], reference, options_));
      result_.detail_slope[f] = slope ? std::max(0.0, *slope) : -1.0;
      if (!slope) {
        return 1.0;
      }
    }
    if (result_.detail_slope[f] < 0) {
      return 1.0;
    }
    return std::pow(std::clamp(result_.detail_slope[f], 0.05, 2.0), options_.sharpness_power);
  }

  const products::TexturedQuad& sourceQuad(const TextureTile& t) const {
    for (const auto& q : model_.quads) {
      if (q.surface_id == t.surface_id) {
        return q;
      }
    }
    return model_.quads.front();
  }

  void finish() {
    result_.fine_vertices = model_.fine.vertices.size();
    setVertexColours(fine_acc_, model_.fine, result_);
    result_.frames_used = static_cast<std::size_t>(std::count(used_.begin(), used_.end(), 1));
    result_.frame_used.assign(used_.begin(), used_.end());
    result_.coverage = result_.texels > 0 ? static_cast<double>(seen_) / result_.texels : 0.0;
    result_.message = std::to_string(result_.textured_tiles) + " of " +
                      std::to_string(tiles_.size()) + " tiles textured from " +
                      std::to_string(result_.frames_used) + " of " +
                      std::to_string(frames_.size()) + " frames";
  }

  products::MapModel& model_;
  const std::vector<CameraFrame>& frames_;
  const ImageLoader& load_;
  const TextureOptions& options_;
  TextureResult& result_;
  std::vector<TextureTile> tiles_;
  Frames fr_;
  std::vector<char> used_;
  std::vector<cv::Vec4f> fine_acc_;
  long long seen_ = 0;
};

}  // namespace

TextureResult textureMap(products::MapModel& model, const std::vector<CameraFrame>& frames,
                         const ImageLoader& load, const TextureOptions& options) {
  TextureResult result;
  Texturer(model, frames, load, options, result).run();
  return result;
}

}  // namespace pmap::texture
