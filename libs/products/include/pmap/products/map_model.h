// The map as the exporters see it (VRML97, glTF, MRPT scene, viewer, report):
// textured rectangles plus coloured fine triangles, in the world frame
// (metres, z up).
//
// Texture convention (doc/outputs.md): a rectangle's corners c0 c1 c2 c3 go
// counter-clockwise seen from the side its normal points to. Texture
// coordinates (s, t) in [0, 1]^2 run s along c0 -> c1 and t along c0 -> c3.
// The texture image's pixel row 0 is the c3-c2 edge (t = 1) and column 0 the
// c0-c3 edge (s = 0): pixel (col, row) covers s in [col, col+1) / W and
// t in [H - row - 1, H - row) / H. VRML's TextureCoordinate uses (s, t)
// directly; glTF's UV is (s, 1 - t).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <cstdint>
#include <map>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "pmap/em/offline_em.h"

namespace pmap::products {

struct TexturedQuad {
  std::int32_t surface_id = -1;
  /// Piece of its surface: long surfaces are textured as several tiles
  /// (0, 1, ... in order along c0 -> c1, then c0 -> c3).
  std::int32_t tile = 0;

  std::array<Eigen::Vector3d, 4> corners;  ///< c0 c1 c2 c3, counter-clockwise from the normal
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  Eigen::Vector3d color{0.8, 0.8, 0.8};  ///< RGB in [0, 1], used without texture
  cv::Mat texture;                       ///< BGR 8-bit, empty: untextured
};

struct ColoredTriangles {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<Eigen::Vector3f> colors;  ///< per vertex, RGB in [0, 1] (empty: one colour)
  Eigen::Vector3d color{0.75, 0.25, 0.2};
};

struct MapModel {
  std::vector<TexturedQuad> quads;
  ColoredTriangles fine;
  /// Robot path (world positions), for scenes and viewers that draw it.
  std::vector<Eigen::Vector3d> path;
  /// Points supporting each surface (em::Surface::support), by surface id;
  /// map.glb gives it to viewers in the rectangles' node extras.
  std::map<std::int32_t, std::int32_t> support;
};

/// The planar map as a model: one quad per surface, coloured by orientation
/// (walls, ceilings and floors, slanted), its normal turned towards the
/// robot's side (the path position nearest to it) so that viewers culling
/// back faces show the side the robot saw; fine triangles with their own
/// vertices (three per triangle), uncoloured; the path; each surface's support.
MapModel buildMapModel(const em::PlanarMap& map, const std::vector<Eigen::Vector3d>& points,
                       const std::vector<Eigen::Vector3d>& path);

/// (s, t) texture coordinates of the four corners, in corner order.

/// Axis-aligned box of everything drawn for the map: rectangle corners, fine
/// triangle vertices and the path; empty() when there is nothing.
Eigen::AlignedBox3d boundingBox(const MapModel& model);

inline std::array<Eigen::Vector2f, 4> quadTexCoords() {
  return {Eigen::Vector2f(0, 0), Eigen::Vector2f(1, 0), Eigen::Vector2f(1, 1),
          Eigen::Vector2f(0, 1)};
}

}  // namespace pmap::products
