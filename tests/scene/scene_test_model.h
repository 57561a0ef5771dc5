// A small map model for the scene tests: a textured wall, an untextured
// floor, two coloured fine triangles and a three-pose path.
#pragma once

#include <opencv2/core.hpp>

#include "pmap/products/map_model.h"

namespace pmap::scene::test {

inline products::TexturedQuad wallQuad(int id, double y, const cv::Mat& texture) {
  products::TexturedQuad q;
  q.surface_id = id;
  q.corners = {Eigen::Vector3d(0, y, 0), Eigen::Vector3d(4, y, 0), Eigen::Vector3d(4, y, 2.5),
               Eigen::Vector3d(0, y, 2.5)};
  q.normal = Eigen::Vector3d(0, -1, 0);
  q.color = Eigen::Vector3d(0.2, 0.4, 0.9);
  q.texture = texture;
  return q;
}

inline products::MapModel smallModel() {
  products::MapModel m;
  cv::Mat texture(16, 32, CV_8UC3, cv::Scalar(30, 160, 220));
  m.quads.push_back(wallQuad(3, 1.0, texture));
  products::TexturedQuad floor;
  floor.surface_id = 7;
  floor.corners = {Eigen::Vector3d(0, -1, 0), Eigen::Vector3d(4, -1, 0), Eigen::Vector3d(4, 1, 0),
                   Eigen::Vector3d(0, 1, 0)};
  floor.color = Eigen::Vector3d(0.8, 0.8, 0.8);
  m.quads.push_back(floor);
  m.fine.vertices = {Eigen::Vector3d(1, -1, 1), Eigen::Vector3d(2, -1, 1),
                     Eigen::Vector3d(2, -1, 2), Eigen::Vector3d(1, -1, 2)};
  m.fine.triangles = {{0, 1, 2}, {0, 2, 3}};
  m.fine.colors = {Eigen::Vector3f(1, 0, 0), Eigen::Vector3f(0, 1, 0), Eigen::Vector3f(0, 0, 1),
                   Eigen::Vector3f(1, 1, 0)};
  m.path = {Eigen::Vector3d(0.5, 0, 0), Eigen::Vector3d(2, 0, 0), Eigen::Vector3d(3.5, 0.1, 0)};
  return m;
}

}  // namespace pmap::scene::test
