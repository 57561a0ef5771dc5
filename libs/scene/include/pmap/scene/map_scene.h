// The planar map as an MRPT scene (doc/report.md): one object per rectangle,
// one for all fine triangles and optional overlays (robot path, raw points,
// ground grid, axes), all in the main viewport, none nested.
#pragma once

#include <mrpt/opengl/COpenGLScene.h>

#include <Eigen/Core>
#include <cstddef>
#include <string>
#include <vector>

#include "pmap/products/map_model.h"

namespace pmap::scene {

/// Names of the scene objects (CRenderizable::getName), for viewers.
namespace object_names {
/// + surface id; the tiles of one textured surface share the name.
inline constexpr const char* kSurfacePrefix = "surface_";
inline constexpr const char* kFineTriangles = "fine_triangles";
inline constexpr const char* kRobotPath = "robot_path";
inline constexpr const char* kPoints = "points";
inline constexpr const char* kGroundGrid = "ground_grid";
inline constexpr const char* kAxes = "axes";
}  // namespace object_names

struct SceneOptions {
  bool add_path = true;   ///< the robot path as a line strip (CSetOfLines)
  bool add_grid = true;   ///< a ground grid (CGridPlaneXY) 5 cm under the lowest map point
  bool add_axes = false;  ///< the world axes at the origin (CAxis)
  double grid_spacing_m = 1.0;
  double axes_length_m = 1.0;
  float point_size_px = 2.0f;
  /// Raw points in the world frame (metres), not owned; nullptr: no cloud.
  const std::vector<Eigen::Vector3d>* points = nullptr;
  /// RGB in [0, 1] per point (as many as points; CPointCloudColoured), or
  /// nullptr: all points in `point_color` (CPointCloud).
  const std::vector<Eigen::Vector3f>* point_colors = nullptr;
  Eigen::Vector3f point_color{0.25f, 0.25f, 0.25f};  ///< RGB in [0, 1]
  Eigen::Vector3f path_color{1.0f, 0.45f, 0.0f};     ///< RGB in [0, 1]
  Eigen::Vector3f grid_color{0.6f, 0.6f, 0.6f};      ///< RGB in [0, 1]
  /// Directional light of the main viewport (saved with the scene): ambient
  /// and diffuse intensities in [0, 1]. MRPT lights one side of a face only,
  /// so a high ambient term keeps back faces readable.
  float light_ambient = 0.6f;
  float light_diffuse = 0.45f;

  /// Empty if valid, otherwise the violated rule.
  std::string validate() const;
};

/// Builds the scene. Rectangles with a texture become a
/// CSetOfTexturedTriangles (two triangles, the texture convention of
/// map_model.h), the others a CSetOfTriangles in the rectangle's colour; all
/// fine triangles one CSetOfTriangles with vertex colours. Throws ConfigError
/// for invalid options and ProcessingError for a fine triangle that names a
/// missing vertex or a texture that is not 8-bit with 1, 3 or 4 channels.
mrpt::opengl::COpenGLScene::Ptr buildMapScene(const products::MapModel& model,
                                              const SceneOptions& options);

/// The number of objects buildMapScene puts into the main viewport:
///   quads + 1 (fine triangles, even if none) + add_path + (points != nullptr)
///   + add_grid + add_axes.
/// Empty inputs keep their object (an empty path is a CSetOfLines without
/// segments), so the count depends on the options and the quad count only.
std::size_t expectedObjectCount(const products::MapModel& model, const SceneOptions& options);

/// Objects of the main viewport, counted recursively: a CSetOfObjects counts
/// as its children.
std::size_t countSceneObjects(const mrpt::opengl::COpenGLScene& scene);

}  // namespace pmap::scene
