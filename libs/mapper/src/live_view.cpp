#include "pmap/mapper/live_view.h"

#include <mrpt/opengl/CPointCloud.h>
#include <mrpt/opengl/stock_objects.h>
#include <mrpt/poses/CPose3D.h>

#include <cstdio>
#include <cstdlib>
#include <thread>

#include "pmap/common/error.h"
#include "pmap/scene/map_scene.h"

namespace pmap::mapper {
namespace {

std::vector<Eigen::Vector3d> pathOf(const points::PointMap& map, std::size_t last) {
  std::vector<Eigen::Vector3d> path;
  for (std::size_t i = 0; i <= last && i < map.scans().size(); ++i) {
    const auto& p = map.scans()[i].robot_pose;
    path.emplace_back(p.x, p.y, p.z);
  }
  return path;
}

// Ceilings face the robot (down): left out so that the view looks in.
products::MapModel withoutCeilings(products::MapModel model) {
  std::vector<products::TexturedQuad> kept;
  for (auto& q : model.quads) {
    if (q.normal.z() > -0.9) {
      kept.push_back(std::move(q));
    }
  }
  model.quads = std::move(kept);
  return model;
}

}  // namespace

LiveView::LiveView(LiveViewOptions options) : options_(std::move(options)) {
  const char* display = std::getenv("DISPLAY");
  if (display == nullptr || *display == '\0') {
    throw ConfigError(
        "--gui needs a display (DISPLAY is not set; on a machine without one, run under "
        "xvfb-run)");
  }
  window_ = mrpt::gui::CDisplayWindow3D::Create("planar-mapper", options_.width, options_.height);
  window_->setCameraElevationDeg(62.0f);
  window_->setCameraZoom(9.0f);
}

bool LiveView::due() const {
  return !shown_ || std::chrono::steady_clock::now() - last_ >=
                        std::chrono::duration<double>(1.0 / options_.max_rate_hz);
}

void LiveView::update(const points::PointMap& map, std::size_t record,
                      const em::PlanarMap* planar) {
  last_ = std::chrono::steady_clock::now();
  shown_ = true;
  products::MapModel model;
  if (planar != nullptr) {
    const std::vector<Eigen::Vector3d> pts(
        map.xyz().begin(),
        map.xyz().begin() + static_cast<std::ptrdiff_t>(planar->assignment.size()));
    model = products::buildMapModel(*planar, pts, pathOf(map, record));
  } else {
    model.path = pathOf(map, record);
  }
  show(model, map, record);
}

void LiveView::show(const products::MapModel& model, const points::PointMap& map,
                    std::size_t record) {
  scene::SceneOptions options;
  options.add_grid = true;
  const bool no_map = model.quads.empty() && model.fine.triangles.empty();
  options.points = no_map ? &map.xyz() : nullptr;  // offline mode: the points until the map
  mrpt::opengl::COpenGLScene::Ptr scene = scene::buildMapScene(withoutCeilings(model), options);
  if (record < map.scans().size()) {
    const points::ScanRecord& s = map.scans()[record];
    auto scan = mrpt::opengl::CPointCloud::Create();
    for (std::size_t i = s.first_point; i < s.first_point + s.num_points; ++i) {
      const Eigen::Vector3d& p = map.xyz()[i];
      scan->insertPoint(static_cast<float>(p.x()), static_cast<float>(p.y()),
                        static_cast<float>(p.z()));
    }
    scan->setColor(1.0, 0.1, 0.1);
    scan->setPointSize(4.0f);
    scene->insert(scan);
    auto robot = mrpt::opengl::stock_objects::RobotPioneer();
    robot->setPose(mrpt::poses::CPose3D(s.robot_pose));
    scene->insert(robot);
    window_->setCameraPointingToPoint(static_cast<float>(s.robot_pose.x),
                                      static_cast<float>(s.robot_pose.y), 0.5f);
    window_->setCameraAzimuthDeg(static_cast<float>(mrpt::RAD2DEG(s.robot_pose.yaw)) + 180.0f);
  }
  window_->get3DSceneAndLock() = scene;
  window_->unlockAccess3DScene();
  window_->forceRepaint();
}

void LiveView::finish(const products::MapModel& model, const points::PointMap& map) {
  show(model, map, map.scans().empty() ? 0 : map.scans().size() - 1);
  if (options_.hold_s < 0) {
    std::fprintf(stderr, "planar-mapper: close the 3D window or press a key in it to exit\n");
  }
  const auto until = std::chrono::steady_clock::now() +
                     std::chrono::duration<double>(options_.hold_s < 0 ? 1e9 : options_.hold_s);
  while (window_->isOpen() && !window_->keyHit() && std::chrono::steady_clock::now() < until) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
}

}  // namespace pmap::mapper
