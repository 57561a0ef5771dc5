// Offscreen renders of the map (mrpt::opengl::CFBORender: EGL, no X server)
// for the report: a perspective view and an orthographic top view.
#pragma once

#include <opencv2/core.hpp>
#include <string>

#include "pmap/products/map_model.h"
#include "pmap/report/view_cameras.h"

namespace pmap::report {

struct MapViews {
  cv::Mat perspective;               ///< 8-bit BGR, options' size; empty when rendering failed
  cv::Mat top;                       ///< 8-bit BGR, options' size; empty when rendering failed
  bool perspective_on_path = false;  ///< the perspective view is on the path (else 3/4)
  /// Empty on success, else one line: why offscreen rendering failed.
  std::string error;
};

/// Renders both views of the scene of libs/scene (white background, ground
/// grid; the top and 3/4 views without ceilings, the top view with wall tops
/// and the path drawn as strips). Never throws for rendering problems (no
/// EGL device, no OpenGL): they are returned in `error`. Throws ConfigError
/// for invalid options and ProcessingError for an invalid model.
MapViews renderMapViews(const products::MapModel& model, const MapViewOptions& options);

}  // namespace pmap::report
