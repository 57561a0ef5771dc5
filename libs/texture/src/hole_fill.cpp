#include "pmap/texture/hole_fill.h"

#include <algorithm>
#include <vector>

namespace pmap::texture {
namespace {

// Normalised colour + confidence in [0, 1] per texel: (b, g, r, a).
cv::Mat normalise(const cv::Mat& acc) {
  cv::Mat out(acc.size(), CV_32FC4);
  for (int r = 0; r < acc.rows; ++r) {
    const auto* in = acc.ptr<cv::Vec4f>(r);
    auto* o = out.ptr<cv::Vec4f>(r);
    for (int c = 0; c < acc.cols; ++c) {
      const float w = in[c][3];
      o[c] =
          w > 0 ? cv::Vec4f(in[c][0] / w, in[c][1] / w, in[c][2] / w, 1.f) : cv::Vec4f(0, 0, 0, 0);
    }
  }
  return out;
}

// Push: 2x2 box-average of premultiplied colours; confidence saturates at 1.
cv::Mat push(const cv::Mat& fine) {
  cv::Mat coarse((fine.rows + 1) / 2, (fine.cols + 1) / 2, CV_32FC4, cv::Scalar::all(0));
  for (int r = 0; r < coarse.rows; ++r) {
    for (int c = 0; c < coarse.cols; ++c) {
      cv::Vec4f sum(0, 0, 0, 0);
      for (int dr = 0; dr < 2; ++dr) {
        for (int dc = 0; dc < 2; ++dc) {
          const int fr = std::min(fine.rows - 1, 2 * r + dr);
          const int fc = std::min(fine.cols - 1, 2 * c + dc);
          const cv::Vec4f& p = fine.at<cv::Vec4f>(fr, fc);
          sum += cv::Vec4f(p[0] * p[3], p[1] * p[3], p[2] * p[3], p[3]);
        }
      }
      coarse.at<cv::Vec4f>(r, c) = sum[3] > 0 ? cv::Vec4f(sum[0] / sum[3], sum[1] / sum[3],
                                                          sum[2] / sum[3], std::min(1.f, sum[3]))
                                              : cv::Vec4f(0, 0, 0, 0);
    }
  }
  return coarse;
}

// Pull: a texel with confidence a keeps a of its colour and takes the rest
// from the (already filled) coarser level, bilinearly.
void pull(cv::Mat& fine, const cv::Mat& coarse) {
  for (int r = 0; r < fine.rows; ++r) {
    for (int c = 0; c < fine.cols; ++c) {
      cv::Vec4f& p = fine.at<cv::Vec4f>(r, c);
      if (p[3] >= 1.f) {
        continue;
      }
      const float y = std::clamp((r - 0.5f) / 2.f, 0.f, coarse.rows - 1.f);
      const float x = std::clamp((c - 0.5f) / 2.f, 0.f, coarse.cols - 1.f);
      const int y0 = static_cast<int>(y), x0 = static_cast<int>(x);
      const int y1 = std::min(coarse.rows - 1, y0 + 1), x1 = std::min(coarse.cols - 1, x0 + 1);
      const float fy = y - y0, fx = x - x0;
      const cv::Vec4f q =
          (1 - fy) * ((1 - fx) * coarse.at<cv::Vec4f>(y0, x0) + fx * coarse.at<cv::Vec4f>(y0, x1)) +
          fy * ((1 - fx) * coarse.at<cv::Vec4f>(y1, x0) + fx * coarse.at<cv::Vec4f>(y1, x1));
      const float a = p[3];
      for (int k = 0; k < 3; ++k) {
        p[k] = a * p[k] + (1 - a) * q[k];
      }
      p[3] = std::max(a, q[3]);
    }
  }
}

}  // namespace

cv::Mat resolveTexture(const cv::Mat& acc, const cv::Vec3f& fallback) {
  std::vector<cv::Mat> levels{normalise(acc)};
  while (levels.back().rows > 1 || levels.back().cols > 1) {
    levels.push_back(push(levels.back()));
  }
  cv::Mat& top = levels.back();
  cv::Vec4f& t = top.at<cv::Vec4f>(0, 0);
  if (t[3] <= 0) {
    t = cv::Vec4f(fallback[0], fallback[1], fallback[2], 1.f);
  } else {
    t[3] = 1.f;
  }
  for (std::size_t k = levels.size() - 1; k-- > 0;) {
    pull(levels[k], levels[k + 1]);
  }
  cv::Mat out(acc.size(), CV_8UC3);
  for (int r = 0; r < acc.rows; ++r) {
    const auto* p = levels[0].ptr<cv::Vec4f>(r);
    auto* o = out.ptr<cv::Vec3b>(r);
    for (int c = 0; c < acc.cols; ++c) {
      o[c] = cv::Vec3b(cv::saturate_cast<uchar>(p[c][0]), cv::saturate_cast<uchar>(p[c][1]),
                       cv::saturate_cast<uchar>(p[c][2]));
    }
  }
  return out;
}

}  // namespace pmap::texture
