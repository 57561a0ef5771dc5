#include "pmap/texture/detail_transfer.h"

#include <opencv2/imgproc.hpp>

#include "pmap/texture/luminance.h"

namespace pmap::texture {
namespace {

constexpr double kHighPassSigmaTexels = 1.5;
constexpr std::size_t kMinTexels = 500;
constexpr double kMinDetailGrey2 = 4.0;  // mean hp(R)^2: 2 grey levels rms

// X minus its local mean over `mask` (normalised convolution); the mask of
// texels whose neighbourhood is mostly inside.
void highPass(const cv::Mat& x, const cv::Mat& mask, cv::Mat& hp, cv::Mat& valid) {
  cv::Mat xm, bx, bm;
  cv::multiply(x, mask, xm);
  cv::GaussianBlur(xm, bx, cv::Size(0, 0), kHighPassSigmaTexels);
  cv::GaussianBlur(mask, bm, cv::Size(0, 0), kHighPassSigmaTexels);
  hp = x - bx / cv::max(bm, 1e-6);
  valid = (bm > 0.8) & (mask > 0);
}

DetailSums tileDetail(const FrameView& view, const TextureTile& tile, const TexelBox& box,
                      const cv::Mat& reference, const TextureOptions& options) {
  const cv::Size size(box.col1 - box.col0 + 1, box.row1 - box.row0 + 1);
  cv::Mat s(size, CV_32F, cv::Scalar(0)), mask(size, CV_32F, cv::Scalar(0));
  sampleTile(tile, box, view, options, [&](int col, int row, const cv::Vec3f& c, float) {
    s.at<float>(row - box.row0, col - box.col0) = luminance(c);
    mask.at<float>(row - box.row0, col - box.col0) = 1.f;
  });
  cv::Mat r(size, CV_32F, cv::Scalar(0));
  for (int row = 0; row < size.height; ++row) {
    for (int col = 0; col < size.width; ++col) {
      const cv::Vec4f& t = reference.at<cv::Vec4f>(row + box.row0, col + box.col0);
      if (t[3] > 0) {
        r.at<float>(row, col) = luminance(cv::Vec3f(t[0], t[1], t[2]) / t[3]);
      } else {
        mask.at<float>(row, col) = 0.f;
      }
    }
  }
  cv::Mat hs, hr, valid, unused;
  highPass(s, mask, hs, valid);
  highPass(r, mask, hr, unused);
  DetailSums d;
  for (int row = 0; row < size.height; ++row) {
    for (int col = 0; col < size.width; ++col) {
      if (valid.at<uchar>(row, col) != 0) {
        const double y = hr.at<float>(row, col);
        d.sxy += hs.at<float>(row, col) * y;
        d.syy += y * y;
        ++d.texels;
      }
    }
  }
  return d;
}

}  // namespace

DetailSums measureDetail(const FrameView& view, const std::vector<TextureTile>& tiles,
                         const std::vector<VisibleTile>& visible,
                         const std::vector<cv::Mat>& reference, const TextureOptions& options) {
  DetailSums sum;
  for (const VisibleTile& v : visible) {
    if (reference[v.tile].empty()) {
      continue;
    }
    const DetailSums d = tileDetail(view, tiles[v.tile], v.box, reference[v.tile], options);
    sum.sxy += d.sxy;
    sum.syy += d.syy;
    sum.texels += d.texels;
  }
  return sum;
}

std::optional<double> detailSlope(const DetailSums& sums) {
  if (sums.texels < kMinTexels || sums.syy < kMinDetailGrey2 * static_cast<double>(sums.texels)) {
    return std::nullopt;
  }
  return sums.sxy / sums.syy;
}

}  // namespace pmap::texture
