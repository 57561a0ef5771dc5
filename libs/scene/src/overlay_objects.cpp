#include "overlay_objects.h"

#include <mrpt/opengl/CAxis.h>
#include <mrpt/opengl/CGridPlaneXY.h>
#include <mrpt/opengl/CPointCloud.h>
#include <mrpt/opengl/CPointCloudColoured.h>
#include <mrpt/opengl/CSetOfLines.h>

#include <Eigen/Geometry>
#include <cmath>

namespace pmap::scene::detail {
namespace {

/// The grid lies this far under the lowest map point: far enough for the
/// depth buffer to keep it under a floor seen from afar.
constexpr double kGridBelowM = 0.05;

}  // namespace

mrpt::opengl::CRenderizable::Ptr pathObject(const std::vector<Eigen::Vector3d>& path,
                                            const Eigen::Vector3f& rgb) {
  auto lines = mrpt::opengl::CSetOfLines::Create();
  for (std::size_t i = 1; i < path.size(); ++i) {
    const Eigen::Vector3d& a = path[i - 1];
    const Eigen::Vector3d& b = path[i];
    lines->appendLine(a.x(), a.y(), a.z(), b.x(), b.y(), b.z());
  }
  lines->setColor(rgb.x(), rgb.y(), rgb.z());
  lines->setName(object_names::kRobotPath);
  return lines;
}

mrpt::opengl::CRenderizable::Ptr pointsObject(const std::vector<Eigen::Vector3d>& points,
                                              const std::vector<Eigen::Vector3f>* colors,
                                              const SceneOptions& options) {
  if (colors != nullptr) {
    auto cloud = mrpt::opengl::CPointCloudColoured::Create();
    for (std::size_t i = 0; i < points.size(); ++i) {
      const Eigen::Vector3f p = points[i].cast<float>();
      const Eigen::Vector3f& c = (*colors)[i];
      cloud->push_back(p.x(), p.y(), p.z(), c.x(), c.y(), c.z());
    }
    cloud->setPointSize(options.point_size_px);
    cloud->setName(object_names::kPoints);
    return cloud;
  }
  auto cloud = mrpt::opengl::CPointCloud::Create();
  for (const auto& p : points) {
    cloud->insertPoint(static_cast<float>(p.x()), static_cast<float>(p.y()),
                       static_cast<float>(p.z()));
  }
  const Eigen::Vector3f& c = options.point_color;
  cloud->setColor(c.x(), c.y(), c.z());
  cloud->setPointSize(options.point_size_px);
  cloud->setName(object_names::kPoints);
  return cloud;
}

mrpt::opengl::CRenderizable::Ptr gridObject(const products::MapModel& model,
                                            const SceneOptions& options) {
  Eigen::AlignedBox3d box = products::boundingBox(model);
  if (box.isEmpty()) {
    box = Eigen::AlignedBox3d(Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero());
  }
  // At most kMaxGridLines lines per axis: the spacing grows by tens with
  // the map's extent (MRPT builds one vertex pair per line).
  constexpr double kMaxGridLines = 1000.0;
  const double extent = std::max(box.max().x() - box.min().x(), box.max().y() - box.min().y());
  double step = options.grid_spacing_m;
  while (std::isfinite(extent) && extent / step > kMaxGridLines) {
    step *= 10.0;
  }
  const auto lower = [step](double v) { return step * std::floor(v / step); };
  const auto upper = [step](double v) { return step * (std::floor(v / step) + 1.0); };
  auto grid = mrpt::opengl::CGridPlaneXY::Create(
      static_cast<float>(lower(box.min().x())), static_cast<float>(upper(box.max().x())),
      static_cast<float>(lower(box.min().y())), static_cast<float>(upper(box.max().y())),
      static_cast<float>(box.min().z() - kGridBelowM), static_cast<float>(step));
  const Eigen::Vector3f& c = options.grid_color;
  grid->setColor(c.x(), c.y(), c.z());
  grid->setName(object_names::kGroundGrid);
  return grid;
}

mrpt::opengl::CRenderizable::Ptr axesObject(const SceneOptions& options) {
  const auto len = static_cast<float>(options.axes_length_m);
  auto axes = mrpt::opengl::CAxis::Create(0.0f, 0.0f, 0.0f, len, len, len, len, 2.0f, false);
  axes->setName(object_names::kAxes);
  return axes;
}

}  // namespace pmap::scene::detail
