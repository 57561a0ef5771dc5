#include "surface_objects.h"

#include <mrpt/img/CImage.h>
#include <mrpt/opengl/CSetOfTexturedTriangles.h>
#include <mrpt/opengl/CSetOfTriangles.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <string>

#include "pmap/common/error.h"
#include "pmap/scene/map_scene.h"

namespace pmap::scene::detail {
namespace {

using mrpt::opengl::TTriangle;

mrpt::img::TColor toColor(const Eigen::Vector3d& rgb) {
  const auto u8 = [](double v) {
    return static_cast<std::uint8_t>(std::lround(255.0 * std::clamp(v, 0.0, 1.0)));
  };
  return {u8(rgb.x()), u8(rgb.y()), u8(rgb.z()), 255};
}

mrpt::math::TPoint3Df toPoint(const Eigen::Vector3d& p) {
  return {static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z())};
}

constexpr std::array<std::array<int, 3>, 2> kQuadTriangles{{{0, 1, 2}, {0, 2, 3}}};

/// Two triangles c0 c1 c2 / c0 c2 c3 with the rectangle's normal. MRPT's
/// texture coordinate v = 0 is the image's first row, our t = 1 (see
/// map_model.h), so (u, v) = (s, 1 - t).
std::array<TTriangle, 2> quadTriangles(const products::TexturedQuad& quad,
                                       const mrpt::img::TColor& color) {
  const auto st = products::quadTexCoords();
  const Eigen::Vector3f n = quad.normal.cast<float>();
  std::array<TTriangle, 2> out;
  for (std::size_t k = 0; k < 2; ++k) {
    for (std::size_t v = 0; v < 3; ++v) {
      const int c = kQuadTriangles[k][v];
      auto& vertex = out[k].vertices[v];
      vertex.xyzrgba.pt = toPoint(quad.corners[c]);
      vertex.setColor(color);
      vertex.normal = {n.x(), n.y(), n.z()};
      vertex.uv = {st[c].x(), 1.0f - st[c].y()};
    }
  }
  return out;
}

cv::Mat bgrTexture(const cv::Mat& texture, std::int32_t surface_id) {
  if (texture.depth() != CV_8U) {
    throw ProcessingError("map model: texture of surface " + std::to_string(surface_id) +
                          " is not 8-bit");
  }
  cv::Mat bgr;
  switch (texture.channels()) {
    case 1:
      cv::cvtColor(texture, bgr, cv::COLOR_GRAY2BGR);
      return bgr;
    case 3:
      return texture.clone();
    case 4:
      cv::cvtColor(texture, bgr, cv::COLOR_BGRA2BGR);
      return bgr;
    default:
      throw ProcessingError("map model: texture of surface " + std::to_string(surface_id) +
                            " has " + std::to_string(texture.channels()) + " channels");
  }
}

}  // namespace

mrpt::opengl::CRenderizable::Ptr quadObject(const products::TexturedQuad& quad) {
  const std::string name = object_names::kSurfacePrefix + std::to_string(quad.surface_id);
  if (quad.texture.empty()) {
    auto obj = mrpt::opengl::CSetOfTriangles::Create();
    for (const auto& t : quadTriangles(quad, toColor(quad.color))) {
      obj->insertTriangle(t);
    }
    obj->setName(name);
    return obj;
  }
  auto obj = mrpt::opengl::CSetOfTexturedTriangles::Create();
  for (const auto& t : quadTriangles(quad, mrpt::img::TColor(255, 255, 255, 255))) {
    obj->insertTriangle(t);
  }
  obj->assignImage(
      mrpt::img::CImage(bgrTexture(quad.texture, quad.surface_id), mrpt::img::DEEP_COPY));
  obj->setName(name);
  return obj;
}

mrpt::opengl::CRenderizable::Ptr fineTrianglesObject(const products::ColoredTriangles& fine) {
  const bool per_vertex = fine.colors.size() == fine.vertices.size();
  const mrpt::img::TColor uniform = toColor(fine.color);
  auto obj = mrpt::opengl::CSetOfTriangles::Create();
  obj->reserve(fine.triangles.size());
  for (std::size_t i = 0; i < fine.triangles.size(); ++i) {
    TTriangle t;
    for (std::size_t v = 0; v < 3; ++v) {
      const std::uint32_t idx = fine.triangles[i][v];
      if (idx >= fine.vertices.size()) {
        throw ProcessingError("map model: fine triangle " + std::to_string(i) + " names vertex " +
                              std::to_string(idx) + " of " + std::to_string(fine.vertices.size()));
      }
      t.vertices[v].xyzrgba.pt = toPoint(fine.vertices[idx]);
      t.vertices[v].setColor(per_vertex ? toColor(fine.colors[idx].cast<double>()) : uniform);
    }
    t.computeNormals();
    obj->insertTriangle(t);
  }
  obj->setName(object_names::kFineTriangles);
  return obj;
}

}  // namespace pmap::scene::detail
