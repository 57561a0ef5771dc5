// Cameras of the report's map pictures: a perspective view from the robot
// path (or a 3/4 view of the whole map) and an orthographic top view.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "pmap/products/map_model.h"

namespace pmap::report {

struct MapViewOptions {
  int width_px = 1280;  ///< both pictures
  int height_px = 720;
  double eye_height_m = 1.6;   ///< perspective camera above the path
  double pitch_down_deg = 8;   ///< perspective camera's downward tilt
  double fov_deg = 65;         ///< vertical field of view of the perspective view
  double min_stretch_m = 1.0;  ///< a shorter straight path stretch gives the 3/4 view
  /// The top and 3/4 views hide horizontal surfaces and fine triangles more
  /// than this above the floor (the median path height, else the lowest map
  /// point): ceilings.
  double ceiling_cut_m = 1.8;
  double footprint_px = 3;  ///< width of wall tops and path in the top view

  /// Empty if valid, otherwise the violated rule.
  std::string validate() const;
};

/// MRPT's orbit camera: the eye is at target + distance * (cos az cos el,
/// sin az cos el, sin el).
struct OrbitCamera {
  Eigen::Vector3d target = Eigen::Vector3d::Zero();
  double azimuth_deg = 0;
  double elevation_deg = 0;
  double distance_m = 1;
  bool orthographic = false;
  double fov_deg = 65;
  Eigen::Vector3d eye() const;
};

/// A straight stretch of the path: from `start` looking at `end`.
struct PathStretch {
  Eigen::Vector3d start = Eigen::Vector3d::Zero(), end = Eigen::Vector3d::Zero();
  double length_m = 0;  ///< horizontal length
};

/// The longest stretch along which the path stays within 0.3 m of the
/// straight line (the first one of equal length); length 0 if none.
PathStretch longestStraightStretch(const std::vector<Eigen::Vector3d>& path);

/// Height of the floor: the median path z, else the lowest map point, else 0.
double floorHeight(const products::MapModel& model);

/// Everything drawn for the map (rectangles, fine triangles, path).
Eigen::AlignedBox3d mapBox(const products::MapModel& model);

struct PerspectiveView {
  OrbitCamera camera;
  bool on_path = false;  ///< on the path, else the 3/4 view
  PathStretch stretch;   ///< the path stretch looked along
};

/// At eye height at the start of the longest straight path stretch, looking
/// along it; a 3/4 view framing `box` when the stretch is shorter than
/// min_stretch_m.
PerspectiveView perspectiveView(const products::MapModel& model, const Eigen::AlignedBox3d& box,
                                const MapViewOptions& options);

/// Straight down (x to the right, y up), orthographic, framing `box` in xy
/// with a 5 % margin.
OrbitCamera topCamera(const Eigen::AlignedBox3d& box, const MapViewOptions& options);

/// Metres per pixel of an orthographic camera in an image of the options'
/// size (MRPT's ortho extent: the shorter image side spans distance / 2).
double topMetresPerPixel(const OrbitCamera& camera, const MapViewOptions& options);

}  // namespace pmap::report
