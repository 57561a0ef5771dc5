// Small maps for the exporter tests: a 4 x 3 x 2.5 m room corner.
#pragma once

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <opencv2/core.hpp>
#include <string>

#include "pmap/products/map_model.h"

namespace pmap::products::test {

/// A BGR texture with a gradient, so that every pixel and row differs.
inline cv::Mat gradientTexture(int width, int height, int seed) {
  cv::Mat image(height, width, CV_8UC3);
  for (int row = 0; row < height; ++row) {
    for (int col = 0; col < width; ++col) {
      image.at<cv::Vec3b>(row, col) = cv::Vec3b(static_cast<uchar>((col * 255) / width),
                                                static_cast<uchar>((row * 255) / height),
                                                static_cast<uchar>((seed * 60 + row + col) % 256));
    }
  }
  return image;
}

inline TexturedQuad quad(std::int32_t id, const Eigen::Vector3d& c0, const Eigen::Vector3d& c1,
                         const Eigen::Vector3d& c3) {
  TexturedQuad q;
  q.surface_id = id;
  q.corners = {c0, c1, c1 + (c3 - c0), c3};
  q.normal = (c1 - c0).cross(c3 - c0).normalized();
  return q;
}

/// Three textured quads: the floor (64x48, non-square) and the wall y = 3 as
/// two tiles (32x32, 16x40: non-square); two untextured ones: the wall x = 0
/// and the ceiling; two coloured fine triangles.
inline MapModel texturedRoomModel() {
  MapModel m;
  m.quads.push_back(quad(3, {0, 0, 0}, {4, 0, 0}, {0, 3, 0}));  // floor, +z
  m.quads.back().texture = gradientTexture(64, 48, 1);
  m.quads.push_back(quad(7, {0, 3, 0}, {2, 3, 0}, {0, 3, 2.5}));  // wall y = 3, -y
  m.quads.back().texture = gradientTexture(32, 32, 2);
  m.quads.push_back(quad(7, {2, 3, 0}, {4, 3, 0}, {2, 3, 2.5}));  // its second tile
  m.quads.back().tile = 1;
  m.quads.back().texture = gradientTexture(16, 40, 3);
  m.quads.push_back(quad(8, {0, 0, 0}, {0, 3, 0}, {0, 0, 2.5}));       // wall x = 0, +x
  m.quads.push_back(quad(12, {0, 0, 2.5}, {0, 3, 2.5}, {4, 0, 2.5}));  // ceiling, -z
  m.quads.back().color = {0.5, 0.25, 1.0};
  m.fine.vertices = {{4, 0, 0}, {4, 1, 0}, {4, 0, 1}, {4, 1, 1}};
  m.fine.triangles = {{0, 1, 2}, {1, 3, 2}};
  m.fine.colors = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}};
  m.path = {{1, 1, 0}, {2, 1.5, 0}};
  return m;
}

inline std::size_t texturedQuadCount(const MapModel& m) {
  std::size_t n = 0;
  for (const TexturedQuad& q : m.quads) {
    n += q.texture.empty() ? 0 : 1;
  }
  return n;
}

/// An empty directory under the test tmp dir.
inline std::filesystem::path freshDir(const std::string& name) {
  // Per process: CTest runs the test cases of one binary in parallel.
  const std::filesystem::path dir =
      std::filesystem::path(PMAP_TEST_TMP_DIR) / "products" / name / std::to_string(::getpid());
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

/// Every file below `dir`, recursively (names relative to it).
inline std::vector<std::string> filesBelow(const std::filesystem::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : std::filesystem::recursive_directory_iterator(dir)) {
    if (e.is_regular_file()) {
      names.push_back(std::filesystem::relative(e.path(), dir).string());
    }
  }
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace pmap::products::test
