#include "pmap/mapper/live_view.h"

#include <mrpt/opengl/CGridPlaneXY.h>
#include <mrpt/opengl/CPointCloud.h>
#include <mrpt/opengl/CSetOfLines.h>
#include <mrpt/opengl/CSetOfTexturedTriangles.h>
#include <mrpt/opengl/CSetOfTriangles.h>
#include <mrpt/opengl/stock_objects.h>
#include <mrpt/poses/CPose3D.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <optional>

#include "gui_thread_sync.h"
#include "pmap/common/error.h"
#include "pmap/scene/map_scene.h"

namespace pmap::mapper {
namespace {

using detail::CanvasProbe;
using detail::Clock;
using detail::ClosableWindow;
using detail::FrameCounter;
using detail::SceneLock;
using detail::waitUntil;

constexpr float kElevationDeg = 62.0f;
constexpr float kFollowZoomM = 9.0f;
constexpr double kMinFramingM = 3.0;
constexpr double kFramingMargin = 1.1;
// Each step of the window's life normally takes milliseconds; the bounds only
// keep a stuck GUI thread from hanging the program.
constexpr const char* kMrptWaitMs = "60000";
constexpr auto kOpenWait = std::chrono::seconds(10);  // after MRPT's own wait
constexpr auto kFirstFrameWait = std::chrono::seconds(20);
constexpr auto kCanvasWait = std::chrono::seconds(60);
constexpr auto kUnrenderedCanvasWait = std::chrono::seconds(2);

/// What the window shows next, prepared without the lock.
struct Content {
  std::vector<mrpt::opengl::TTriangle> triangles;
  std::vector<mrpt::opengl::CRenderizable::Ptr> textured;
  std::vector<mrpt::math::TSegment3D> path;
  std::vector<mrpt::math::TSegment3D> loops;  ///< accepted loop closures
  std::array<std::vector<float>, 3> points;   ///< x, y, z
  std::array<std::vector<float>, 3> scan;
  std::optional<mrpt::poses::CPose3D> robot;
  std::array<float, 6> grid{};  ///< x min, x max, y min, y max, z, spacing
  mrpt::opengl::TLightParameters light;
};

/// NaN: left as it is (the user may have changed it with the mouse).
struct CameraChange {
  Eigen::Vector3f target = Eigen::Vector3f::Constant(std::numeric_limits<float>::quiet_NaN());
  float azimuth_deg = std::numeric_limits<float>::quiet_NaN();
  float distance_m = std::numeric_limits<float>::quiet_NaN();
  float elevation_deg = std::numeric_limits<float>::quiet_NaN();
};

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

void appendPoints(std::array<std::vector<float>, 3>& out, const std::vector<Eigen::Vector3d>& xyz,
                  std::size_t first, std::size_t count) {
  for (std::size_t i = first; i < first + count && i < xyz.size(); ++i) {
    for (int k = 0; k < 3; ++k) {
      out[k].push_back(static_cast<float>(xyz[i][k]));
    }
  }
}

/// The contents of the objects MRPT's map scene (scene::buildMapScene) is
/// made of: the same triangles, path, grid and light as map.3Dscene.
Content contentOf(const products::MapModel& model) {
  scene::SceneOptions options;
  options.add_grid = true;
  const auto fresh = scene::buildMapScene(model, options);  // never rendered
  Content c;
  for (const auto& obj : *fresh->getViewport()) {
    if (const auto tris = std::dynamic_pointer_cast<mrpt::opengl::CSetOfTriangles>(obj)) {
      const auto& buffer = tris->shaderTrianglesBuffer();
      c.triangles.insert(c.triangles.end(), buffer.begin(), buffer.end());
    } else if (std::dynamic_pointer_cast<mrpt::opengl::CSetOfTexturedTriangles>(obj)) {
      c.textured.push_back(obj);
    } else if (const auto lines = std::dynamic_pointer_cast<mrpt::opengl::CSetOfLines>(obj)) {
      c.path.assign(lines->begin(), lines->end());
    } else if (const auto grid = std::dynamic_pointer_cast<mrpt::opengl::CGridPlaneXY>(obj)) {
      grid->getPlaneLimits(c.grid[0], c.grid[1], c.grid[2], c.grid[3]);
      c.grid[4] = grid->getPlaneZcoord();
      c.grid[5] = grid->getGridFrequency();
    }
  }
  c.light = fresh->getViewport()->lightParameters();
  return c;
}

}  // namespace

CameraFraming frameBox(const Eigen::AlignedBox3d& box, double fov_deg) {
  CameraFraming f;
  f.distance_m = kMinFramingM;
  if (box.isEmpty()) {
    return f;
  }
  f.target = box.center();
  const double radius = 0.5 * box.diagonal().norm();
  const double half_fov = 0.5 * std::clamp(fov_deg, 1.0, 170.0) * M_PI / 180.0;
  f.distance_m = std::max(kMinFramingM, kFramingMargin * radius / std::sin(half_fov));
  return f;
}

// The map's box; the points' too while there is no map yet.
Eigen::AlignedBox3d mapBounds(const products::MapModel& model, const points::PointMap& map) {
  Eigen::AlignedBox3d box = products::boundingBox(model);
  if (model.quads.empty() && model.fine.triangles.empty()) {
    for (const auto& p : map.xyz()) {
      box.extend(p);
    }
  }
  return box;
}

/// The window and the objects of its scene, created once; changed only
/// under the scene lock, never removed while the window may render them.
struct LiveView::Window {
  std::shared_ptr<ClosableWindow> window;
  mrpt::opengl::CGridPlaneXY::Ptr grid = mrpt::opengl::CGridPlaneXY::Create();
  mrpt::opengl::CSetOfTriangles::Ptr surfaces = mrpt::opengl::CSetOfTriangles::Create();
  mrpt::opengl::CSetOfObjects::Ptr textured = mrpt::opengl::CSetOfObjects::Create();
  mrpt::opengl::CSetOfLines::Ptr path = mrpt::opengl::CSetOfLines::Create();
  mrpt::opengl::CSetOfLines::Ptr loops = mrpt::opengl::CSetOfLines::Create();
  mrpt::opengl::CPointCloud::Ptr points = mrpt::opengl::CPointCloud::Create();
  mrpt::opengl::CPointCloud::Ptr scan = mrpt::opengl::CPointCloud::Create();
  mrpt::opengl::CSetOfObjects::Ptr robot = mrpt::opengl::stock_objects::RobotPioneer();
  std::shared_ptr<CanvasProbe> probe = std::make_shared<CanvasProbe>();
  FrameCounter frames;
  bool textured_shown = false;

  explicit Window(const LiveViewOptions& options);
  ~Window();
  void apply(Content& c, const CameraChange& camera);
  void close();
};

LiveView::Window::Window(const LiveViewOptions& options) {
  // MRPT gives up starting its GUI thread, and waiting for the window, after
  // 5-6 s unless MRPT_WXSUBSYS_TIMEOUT_MS says otherwise: short on a loaded
  // machine (the window then opens later, or never, unknown to the caller).
  setenv("MRPT_WXSUBSYS_TIMEOUT_MS", kMrptWaitMs, 0);
  window = std::make_shared<ClosableWindow>("planar-mapper", options.width, options.height);
  if (!waitUntil([this] { return window->isOpen(); }, kOpenWait)) {
    // MRPT may still create it later, using the object: never destroy it.
    new std::shared_ptr<ClosableWindow>(window);
    throw ProcessingError("--gui: the 3D window did not open");
  }
  const scene::SceneOptions style;
  grid->setColor(style.grid_color.x(), style.grid_color.y(), style.grid_color.z());
  path->setColor(style.path_color.x(), style.path_color.y(), style.path_color.z());
  points->setColor(style.point_color.x(), style.point_color.y(), style.point_color.z());
  points->setPointSize(style.point_size_px);
  scan->setColor(1.0, 0.1, 0.1);
  scan->setPointSize(4.0f);
  loops->setColor(0.9, 0.1, 0.9);  // magenta: the loop closures
  loops->setLineWidth(3.0f);
  robot->setVisibility(false);
  const std::vector<mrpt::opengl::CRenderizable::Ptr> objects{
      grid, surfaces, textured, path, loops, points, scan, robot, probe};
  SceneLock lock(*window);
  for (const auto& obj : objects) {
    lock.viewport().insert(obj);
  }
  frames.observeBegin(lock.viewport());
  window->setCameraElevationDeg(kElevationDeg);
  window->setCameraZoom(kFollowZoomM);
}

void LiveView::Window::apply(Content& c, const CameraChange& camera) {
  SceneLock lock(*window);
  surfaces->clearTriangles();
  surfaces->insertTriangles(c.triangles.begin(), c.triangles.end());
  if (!c.textured.empty() && !textured_shown) {  // added once, never removed
    textured->insert(c.textured.begin(), c.textured.end());
    textured_shown = true;
  }
  path->clear();
  path->appendLines(c.path);
  loops->clear();
  loops->appendLines(c.loops);
  points->setAllPoints(c.points[0], c.points[1], c.points[2]);
  scan->setAllPoints(c.scan[0], c.scan[1], c.scan[2]);
  robot->setVisibility(c.robot.has_value());
  if (c.robot) {
    robot->setPose(*c.robot);
  }
  grid->setPlaneLimits(c.grid[0], c.grid[1], c.grid[2], c.grid[3]);
  grid->setPlaneZcoord(c.grid[4]);
  grid->setGridFrequency(c.grid[5]);
  lock.viewport().lightParameters() = c.light;
  // The GUI thread reads the camera while it renders, under this lock.
  if (!camera.target.hasNaN()) {
    window->setCameraPointingToPoint(camera.target.x(), camera.target.y(), camera.target.z());
  }
  if (!std::isnan(camera.azimuth_deg)) {
    window->setCameraAzimuthDeg(camera.azimuth_deg);
  }
  if (!std::isnan(camera.elevation_deg)) {
    window->setCameraElevationDeg(camera.elevation_deg);
  }
  if (!std::isnan(camera.distance_m)) {
    window->setCameraZoom(camera.distance_m);
  }
}

// MRPT renders a window whose close was requested until the GUI thread
// deletes its frame; ~CDisplayWindow3D does not wait for that. The canvas
// keeps the scene it last rendered and frees its objects' OpenGL resources
// when destroyed: once one frame is rendered, CanvasProbe tells when the
// canvas is gone and the window object may go.
void LiveView::Window::close() {
  if (window->isOpen() && frames.count() == 0) {
    window->forceRepaint();
    waitUntil([this] { return frames.count() > 0 || !window->isOpen(); }, kFirstFrameWait);
  }
  const bool rendered = frames.count() > 0;
  window->requestClose();
  const bool canvas_gone = probe->waitFreed(rendered ? kCanvasWait : kUnrenderedCanvasWait);
  {
    SceneLock lock(*window);
    frames.observeEnd(lock.viewport());
  }
  if (!canvas_gone || window->isOpen()) {
    if (rendered) {
      std::fprintf(stderr, "planar-mapper: warning: the 3D window did not close in time\n");
    }
    new std::shared_ptr<ClosableWindow>(window);  // the GUI thread may still use it
  }
  window.reset();  // ~CDisplayWindow3D: the window is closed and its canvas gone
}

LiveView::Window::~Window() {
  try {
    close();
  } catch (...) {  // a destructor: nothing left to do
  }
}

LiveView::LiveView(LiveViewOptions options) : options_(std::move(options)) {
  const char* display = std::getenv("DISPLAY");
  if (display == nullptr || *display == '\0') {
    throw ConfigError(
        "--gui needs a display (DISPLAY is not set; on a machine without one, run under "
        "xvfb-run)");
  }
  window_ = std::make_unique<Window>(options_);
}

LiveView::~LiveView() = default;

bool LiveView::due() const {
  return !shown_ ||
         Clock::now() - last_ >= std::chrono::duration<double>(1.0 / options_.max_rate_hz);
}

void LiveView::setLoops(std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> segments) {
  loops_ = std::move(segments);
}

void LiveView::update(const points::PointMap& map, std::size_t record,
                      const em::PlanarMap* planar) {
  last_ = Clock::now();
  shown_ = true;
  if (!window_->window->isOpen()) {
    return;
  }
  products::MapModel model;
  if (planar != nullptr) {
    const std::vector<Eigen::Vector3d> pts(
        map.xyz().begin(),
        map.xyz().begin() + static_cast<std::ptrdiff_t>(planar->assignment.size()));
    model = products::buildMapModel(*planar, pts, pathOf(map, record));
  } else {
    model.path = pathOf(map, record);
  }
  show(model, map, record, false);
}

void LiveView::show(const products::MapModel& model, const points::PointMap& map,
                    std::size_t record, bool final_map) {
  Content c = contentOf(withoutCeilings(model));
  for (const auto& [a, b] : loops_) {
    c.loops.emplace_back(mrpt::math::TPoint3D(a.x(), a.y(), a.z()),
                         mrpt::math::TPoint3D(b.x(), b.y(), b.z()));
  }
  if (model.quads.empty() && model.fine.triangles.empty()) {
    appendPoints(c.points, map.xyz(), 0, map.size());  // offline mode: the points until the map
  }
  CameraChange camera;
  if (record < map.scans().size()) {
    const points::ScanRecord& s = map.scans()[record];
    appendPoints(c.scan, map.xyz(), s.first_point, s.num_points);
    c.robot = mrpt::poses::CPose3D(s.robot_pose);
    camera.target = Eigen::Vector3f(static_cast<float>(s.robot_pose.x),
                                    static_cast<float>(s.robot_pose.y), 0.5f);
    camera.azimuth_deg = static_cast<float>(mrpt::RAD2DEG(s.robot_pose.yaw)) + 180.0f;
  }
  if (final_map) {
    const CameraFraming f = frameBox(mapBounds(model, map), window_->window->getFOV());
    camera.target = f.target.cast<float>();
    camera.distance_m = static_cast<float>(f.distance_m);
    camera.elevation_deg = kElevationDeg;
  } else {
    c.textured.clear();  // the live map is untextured; textures belong to the final map
  }
  window_->apply(c, camera);
  window_->window->forceRepaint();
}

void LiveView::finish(const products::MapModel& model, const points::PointMap& map) {
  show(model, map, map.scans().empty() ? 0 : map.scans().size() - 1, true);
  if (options_.hold_s < 0) {
    std::fprintf(stderr, "planar-mapper: close the 3D window or press a key in it to exit\n");
  }
  auto& window = *window_->window;
  const auto until =
      Clock::now() + std::chrono::duration<double>(options_.hold_s < 0 ? 1e9 : options_.hold_s);
  while (window.isOpen() && !window.keyHit() && Clock::now() < until) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
}

LiveViewState LiveView::state() const {
  LiveViewState s;
  Window& w = *window_;
  SceneLock lock(*w.window);
  for (const auto& obj : lock.viewport()) {
    s.objects.push_back(obj.get());
  }
  s.surface_triangles = w.surfaces->getTrianglesCount();
  s.textured_objects = w.textured->size();
  s.path_segments = w.path->size();
  s.loop_segments = w.loops->size();
  s.map_points = w.points->size();
  s.scan_points = w.scan->size();
  w.window->getCameraPointingToPoint(s.camera_target.x(), s.camera_target.y(), s.camera_target.z());
  s.camera_distance_m = w.window->getCameraZoom();
  s.frames_rendered = w.frames.count();
  return s;
}

}  // namespace pmap::mapper
