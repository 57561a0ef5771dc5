#include "pmap/scene/map_scene.h"

#include <mrpt/opengl/CSetOfObjects.h>

#include <cmath>

#include "overlay_objects.h"
#include "pmap/common/error.h"
#include "surface_objects.h"

namespace pmap::scene {
namespace {

bool finitePositive(double v) {
  return std::isfinite(v) && v > 0.0;
}

bool inUnitRange(float v) {
  return std::isfinite(v) && v >= 0.0f && v <= 1.0f;
}

void setLight(mrpt::opengl::COpenGLViewport& viewport, const SceneOptions& options) {
  auto& light = viewport.lightParameters();
  const float a = options.light_ambient;
  const float d = options.light_diffuse;
  light.ambient = {a, a, a, 1.0f};
  light.diffuse = {d, d, d, 1.0f};
}

std::size_t countObjects(const mrpt::opengl::CSetOfObjects& set) {
  std::size_t n = 0;
  for (const auto& obj : set) {
    const auto* inner = dynamic_cast<const mrpt::opengl::CSetOfObjects*>(obj.get());
    n += inner != nullptr ? countObjects(*inner) : (obj ? 1 : 0);
  }
  return n;
}

}  // namespace

std::string SceneOptions::validate() const {
  if (!finitePositive(grid_spacing_m)) {
    return "grid_spacing_m must be > 0";
  }
  if (!finitePositive(axes_length_m)) {
    return "axes_length_m must be > 0";
  }
  if (!(std::isfinite(point_size_px) && point_size_px > 0.0f)) {
    return "point_size_px must be > 0";
  }
  if (point_colors != nullptr && (points == nullptr || point_colors->size() != points->size())) {
    return "point_colors must have one colour per point";
  }
  if (!inUnitRange(light_ambient) || !inUnitRange(light_diffuse)) {
    return "light_ambient and light_diffuse must be in [0, 1]";
  }
  return {};
}

mrpt::opengl::COpenGLScene::Ptr buildMapScene(const products::MapModel& model,
                                              const SceneOptions& options) {
  if (const std::string rule = options.validate(); !rule.empty()) {
    throw ConfigError("scene options: " + rule);
  }
  auto scene = mrpt::opengl::COpenGLScene::Create();
  for (const auto& quad : model.quads) {
    scene->insert(detail::quadObject(quad));
  }
  scene->insert(detail::fineTrianglesObject(model.fine));
  if (options.add_path) {
    scene->insert(detail::pathObject(model.path, options.path_color));
  }
  if (options.points != nullptr) {
    scene->insert(detail::pointsObject(*options.points, options.point_colors, options));
  }
  if (options.add_grid) {
    scene->insert(detail::gridObject(model, options));
  }
  if (options.add_axes) {
    scene->insert(detail::axesObject(options));
  }
  setLight(*scene->getViewport(), options);
  return scene;
}

std::size_t expectedObjectCount(const products::MapModel& model, const SceneOptions& options) {
  return model.quads.size() + 1 + (options.add_path ? 1 : 0) + (options.points ? 1 : 0) +
         (options.add_grid ? 1 : 0) + (options.add_axes ? 1 : 0);
}

std::size_t countSceneObjects(const mrpt::opengl::COpenGLScene& scene) {
  const auto viewport = scene.getViewport();
  if (!viewport) {
    return 0;
  }
  std::size_t n = 0;
  for (const auto& obj : *viewport) {
    const auto* inner = dynamic_cast<const mrpt::opengl::CSetOfObjects*>(obj.get());
    n += inner != nullptr ? countObjects(*inner) : (obj ? 1 : 0);
  }
  return n;
}

}  // namespace pmap::scene
