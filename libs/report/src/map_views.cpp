#include "pmap/report/map_views.h"

#include <mrpt/img/CImage.h>
#include <mrpt/opengl/CFBORender.h>

#include <algorithm>
#include <exception>

#include "pmap/common/error.h"
#include "pmap/common/text.h"
#include "pmap/scene/map_scene.h"
#include "view_models.h"

namespace pmap::report {
namespace {

using mrpt::opengl::COpenGLScene;

const Eigen::Vector3d kPathRgb{1.0, 0.45, 0.0};

mrpt::opengl::CCamera toMrpt(const OrbitCamera& c) {
  mrpt::opengl::CCamera cam;
  cam.setPointingAt(static_cast<float>(c.target.x()), static_cast<float>(c.target.y()),
                    static_cast<float>(c.target.z()));
  cam.setAzimuthDegrees(static_cast<float>(c.azimuth_deg));
  cam.setElevationDegrees(static_cast<float>(c.elevation_deg));
  cam.setZoomDistance(static_cast<float>(c.distance_m));
  cam.setProjectiveModel(!c.orthographic);
  cam.setProjectiveFOVdeg(static_cast<float>(c.fov_deg));
  return cam;
}

COpenGLScene::Ptr viewScene(const products::MapModel& model, const Eigen::AlignedBox3d& box,
                            bool with_path) {
  scene::SceneOptions so;
  so.add_path = with_path;
  so.add_grid = true;
  so.grid_color = {0.8f, 0.8f, 0.8f};
  auto s = scene::buildMapScene(model, so);
  auto viewport = s->getViewport();
  viewport->setCustomBackgroundColor({1.0f, 1.0f, 1.0f, 1.0f});
  const double extent = box.isEmpty() ? 10.0 : box.diagonal().norm();
  viewport->setViewportClipDistances(0.1f, static_cast<float>(10.0 * extent + 100.0));
  return s;
}

cv::Mat render(mrpt::opengl::CFBORender& renderer, const COpenGLScene& s, const OrbitCamera& c) {
  renderer.setCamera(s, toMrpt(c));
  mrpt::img::CImage rgb;
  renderer.render_RGB(s, rgb);
  return rgb.asCvMat<cv::Mat>(mrpt::img::DEEP_COPY);
}

}  // namespace

MapViews renderMapViews(const products::MapModel& model, const MapViewOptions& options) {
  if (const std::string rule = options.validate(); !rule.empty()) {
    throw ConfigError("map view options: " + rule);
  }
  const Eigen::AlignedBox3d box = mapBox(model);
  const products::MapModel open_model =
      detail::withoutCeilings(model, floorHeight(model), options.ceiling_cut_m);
  const PerspectiveView persp = perspectiveView(model, box, options);
  const OrbitCamera top_cam = topCamera(mapBox(open_model), options);
  products::MapModel top_model = open_model;
  detail::addFootprints(top_model, options.footprint_px * topMetresPerPixel(top_cam, options),
                        kPathRgb);
  // A 3/4 view looks from outside: without ceilings, like the top view.
  const auto persp_scene = viewScene(persp.on_path ? model : open_model, box, true);
  const auto top_scene = viewScene(top_model, box, false);
  MapViews views;
  try {
    mrpt::opengl::CFBORender renderer(static_cast<unsigned>(options.width_px),
                                      static_cast<unsigned>(options.height_px));
    views.perspective = render(renderer, *persp_scene, persp.camera);
    views.top = render(renderer, *top_scene, top_cam);
    views.perspective_on_path = persp.on_path;
  } catch (const std::exception& e) {
    views = MapViews{};
    views.error =
        "offscreen rendering unavailable (EGL with Mesa's software device; Debian packages "
        "libegl1 libegl-mesa0 libgl1-mesa-dri): " +
        oneLineError(e.what());
  }
  return views;
}

}  // namespace pmap::report
