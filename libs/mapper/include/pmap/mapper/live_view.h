// planar-mapper --gui: a live 3D window while mapping (MRPT's
// CDisplayWindow3D, as icp-slam shows its progress). It shows the growing
// map (rectangles coloured by orientation, fine triangles, ceilings left out
// so the view looks in), the path, the points of the current structure scan
// and the robot, with the camera following the robot; at the end, the final
// textured map.
#pragma once

#include <mrpt/gui/CDisplayWindow3D.h>

#include <chrono>

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

class LiveView {
 public:
  /// Opens the window. Throws ConfigError when there is no display.
  explicit LiveView(LiveViewOptions options);

  /// True when the window is due for an update (at most max_rate_hz a second).
  bool due() const;

  /// Shows the state after placing scan `record` of `map`: `planar` is the
  /// map so far (may be null: the points are shown instead).
  void update(const points::PointMap& map, std::size_t record, const em::PlanarMap* planar);

  /// Shows the final map, then waits (LiveViewOptions::hold_s).
  void finish(const products::MapModel& model, const points::PointMap& map);

 private:
  void show(const products::MapModel& model, const points::PointMap& map, std::size_t record);

  LiveViewOptions options_;
  mrpt::gui::CDisplayWindow3D::Ptr window_;
  std::chrono::steady_clock::time_point last_;
  bool shown_ = false;
};

}  // namespace pmap::mapper
