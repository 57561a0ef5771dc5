// planar-mapper --gui: a live 3D window while mapping (MRPT's
// CDisplayWindow3D, as icp-slam shows its progress). It shows the growing
// map (rectangles coloured by orientation, fine triangles, ceilings left out
// so the view looks in), the path, the loop closures accepted so far (a
// magenta line between the two keyframes of each), the points of the
// current structure scan and the robot, with the camera following the robot; at the end, the final
// textured map, framed whole.
//
// Threads (MRPT 2.5.8): the window is drawn by MRPT's GUI thread, which
// renders the window's scene while it holds the scene lock
// (get3DSceneAndLock) and creates the OpenGL buffers and textures of the
// objects it renders. LiveView builds its scene objects once and never
// removes one while the window is open: each update changes their contents
// under the lock, and the GUI thread re-uploads them. On destruction it closes
// the window and waits until the GUI thread has destroyed the window's GL
// canvas (which frees the objects' OpenGL resources on that thread) before it
// lets the window object go: the GUI thread may still paint the window, and
// use the window object, after MRPT's close request returns.
#pragma once

#include <Eigen/Geometry>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "pmap/em/offline_em.h"
#include "pmap/points/point_map.h"
#include "pmap/products/map_model.h"

namespace pmap::mapper {

struct LiveViewOptions {
  double max_rate_hz = 10.0;  ///< window updates per second at most
  /// At the end: >= 0 keeps the final map shown this many seconds, then
  /// returns; < 0 waits until the window is closed or a key is pressed.
  double hold_s = -1.0;
  int width = 1024;
  int height = 720;
};

/// Where the camera looks from to show a whole box.
struct CameraFraming {
  Eigen::Vector3d target = Eigen::Vector3d::Zero();  ///< point looked at (m)
  double distance_m = 0.0;                           ///< eye distance (MRPT's zoom, m)
};

/// The camera pointing at the centre of `box`, far enough for the sphere
/// around the box to fit a vertical field of view of `fov_deg` (with a 10 %
/// margin), and at least 3 m away. An empty box frames the origin.
CameraFraming frameBox(const Eigen::AlignedBox3d& box, double fov_deg);

/// The box of what the final view shows: the rectangles' corners, the fine
/// triangles' vertices and the path; the points of `map` too when the model
/// has neither rectangles nor fine triangles (mapping stopped before the EM).
Eigen::AlignedBox3d mapBounds(const products::MapModel& model, const points::PointMap& map);

/// What the window shows, read under the scene lock (for tests).
struct LiveViewState {
  /// Identities of the objects of the window's main viewport, in order.
  std::vector<const void*> objects;
  std::size_t surface_triangles = 0;  ///< untextured rectangles and fine triangles
  std::size_t textured_objects = 0;   ///< textured rectangles (the final map)
  std::size_t path_segments = 0;
  std::size_t loop_segments = 0;  ///< loop closures shown
  std::size_t map_points = 0;     ///< points shown while there is no map
  std::size_t scan_points = 0;    ///< the current structure scan
  Eigen::Vector3f camera_target = Eigen::Vector3f::Zero();
  float camera_distance_m = 0.0f;
  std::uint64_t frames_rendered = 0;  ///< by MRPT's GUI thread so far
};

class LiveView {
 public:
  /// Opens the window. Throws ConfigError when there is no display and
  /// ProcessingError when the window does not open.
  explicit LiveView(LiveViewOptions options);
  /// Closes the window and waits until MRPT's GUI thread let go of it.
  ~LiveView();
  LiveView(const LiveView&) = delete;
  LiveView& operator=(const LiveView&) = delete;

  /// True when the window is due for an update (at most max_rate_hz a second).
  bool due() const;

  /// Shows the state after placing scan `record` of `map`: `planar` is the
  /// map so far (may be null: the points are shown instead).
  void update(const points::PointMap& map, std::size_t record, const em::PlanarMap* planar);

  /// The loop closures to show from the next update on: one segment per
  /// closure, between its two keyframes' positions (m).
  void setLoops(std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> segments);

  /// Shows the final map framed whole (mapBounds, frameBox), then waits
  /// (LiveViewOptions::hold_s). Call once, after the last update.
  void finish(const products::MapModel& model, const points::PointMap& map);

  LiveViewState state() const;

 private:
  struct Window;
  void show(const products::MapModel& model, const points::PointMap& map, std::size_t record,
            bool final_map);

  LiveViewOptions options_;
  std::unique_ptr<Window> window_;
  std::chrono::steady_clock::time_point last_;
  bool shown_ = false;
  std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> loops_;
};

}  // namespace pmap::mapper
