// A synthetic corridor for the report tests: 10 m along x, 2 m wide, 2.5 m
// high; a grey floor, a green wall (y = -1), a magenta-textured wall (y = 1),
// a blue ceiling, a red fine-triangle patch and a straight path along x.
#pragma once

#include <opencv2/core.hpp>

#include "pmap/products/map_model.h"

namespace pmap::report::test {

inline products::TexturedQuad rect(int id, std::array<Eigen::Vector3d, 4> corners,
                                   const Eigen::Vector3d& normal, const Eigen::Vector3d& rgb) {
  products::TexturedQuad q;
  q.surface_id = id;
  q.corners = corners;
  q.normal = normal;
  q.color = rgb;
  return q;
}

inline products::MapModel corridor() {
  using V = Eigen::Vector3d;
  products::MapModel m;
  m.quads.push_back(rect(0, {V(0, -1, 0), V(10, -1, 0), V(10, 1, 0), V(0, 1, 0)}, V(0, 0, 1),
                         V(0.75, 0.75, 0.75)));
  m.quads.push_back(rect(1, {V(0, -1, 0), V(10, -1, 0), V(10, -1, 2.5), V(0, -1, 2.5)}, V(0, 1, 0),
                         V(0.1, 0.8, 0.2)));
  auto textured = rect(2, {V(10, 1, 0), V(0, 1, 0), V(0, 1, 2.5), V(10, 1, 2.5)}, V(0, -1, 0),
                       V(0.5, 0.5, 0.5));
  textured.texture = cv::Mat(64, 256, CV_8UC3, cv::Scalar(210, 20, 210));  // BGR magenta
  for (int c = 0; c < 256; c += 32) {
    textured.texture.colRange(c, c + 8).setTo(cv::Scalar(255, 255, 255));
  }
  m.quads.push_back(textured);
  m.quads.push_back(rect(3, {V(0, 1, 2.5), V(10, 1, 2.5), V(10, -1, 2.5), V(0, -1, 2.5)},
                         V(0, 0, -1), V(0.3, 0.3, 0.9)));
  m.fine.vertices = {V(6, -0.9, 0.5), V(7, -0.9, 0.5), V(7, -0.9, 1.5), V(6, -0.9, 1.5)};
  m.fine.triangles = {{0, 1, 2}, {0, 2, 3}};
  m.fine.color = V(0.9, 0.1, 0.1);
  for (int i = 0; i <= 18; ++i) {
    m.path.emplace_back(0.5 + 0.5 * i, 0.02 * (i % 2), 0.0);
  }
  return m;
}

/// Pixels whose colour satisfies `pred(b, g, r)`.
template <typename Pred>
int countPixels(const cv::Mat& bgr, Pred pred) {
  int n = 0;
  for (int y = 0; y < bgr.rows; ++y) {
    for (int x = 0; x < bgr.cols; ++x) {
      const cv::Vec3b p = bgr.at<cv::Vec3b>(y, x);
      n += pred(p[0], p[1], p[2]) ? 1 : 0;
    }
  }
  return n;
}

inline bool greenish(int b, int g, int r) {
  return g > r + 60 && g > b + 60;
}
inline bool magentaish(int b, int g, int r) {
  return r > g + 60 && b > g + 60;
}
inline bool orangeish(int b, int g, int r) {
  return r > 200 && g > 60 && g < 170 && b < 70;
}

/// Standard deviation of the grey levels.
inline double greyStdDev(const cv::Mat& bgr) {
  cv::Scalar mean, stddev;
  cv::meanStdDev(bgr.reshape(1), mean, stddev);
  return stddev[0];
}

}  // namespace pmap::report::test
