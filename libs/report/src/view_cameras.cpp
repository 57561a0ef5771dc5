#include "pmap/report/view_cameras.h"

#include <algorithm>
#include <cmath>

namespace pmap::report {
namespace {

constexpr double kDeg = M_PI / 180.0;
constexpr double kSampleSpacingM = 0.25;
constexpr double kMaxLateralM = 0.3;
constexpr std::size_t kMaxRunSamples = 400;

Eigen::Vector2d xy(const Eigen::Vector3d& p) {
  return p.head<2>();
}

/// Path positions at least kSampleSpacingM apart (horizontally).
std::vector<Eigen::Vector3d> resample(const std::vector<Eigen::Vector3d>& path) {
  std::vector<Eigen::Vector3d> out;
  for (const auto& p : path) {
    if (p.allFinite() && (out.empty() || (xy(p) - xy(out.back())).norm() >= kSampleSpacingM)) {
      out.push_back(p);
    }
  }
  return out;
}

bool straight(const std::vector<Eigen::Vector3d>& p, std::size_t i, std::size_t j) {
  const Eigen::Vector2d a = xy(p[i]);
  const Eigen::Vector2d d = (xy(p[j]) - a).normalized();
  double along = 0;
  for (std::size_t k = i + 1; k < j; ++k) {
    const Eigen::Vector2d v = xy(p[k]) - a;
    const double s = v.dot(d);
    if (std::abs(d.x() * v.y() - d.y() * v.x()) > kMaxLateralM || s < along - kMaxLateralM) {
      return false;
    }
    along = std::max(along, s);
  }
  return true;
}

double aspect(const MapViewOptions& o) {
  return static_cast<double>(o.width_px) / static_cast<double>(o.height_px);
}

OrbitCamera threeQuarterCamera(const Eigen::AlignedBox3d& box, const MapViewOptions& o) {
  OrbitCamera c;
  c.target = box.center();
  c.azimuth_deg = -120;
  c.elevation_deg = 40;
  c.fov_deg = o.fov_deg;
  const double radius = std::max(0.5, 0.5 * box.diagonal().norm());
  const double half_fov = 0.5 * o.fov_deg * kDeg * std::min(1.0, aspect(o));
  c.distance_m = 1.05 * radius / std::sin(half_fov);
  return c;
}

}  // namespace

std::string MapViewOptions::validate() const {
  if (width_px < 16 || height_px < 16 || width_px > 8192 || height_px > 8192) {
    return "width_px and height_px must be in [16, 8192]";
  }
  if (!(eye_height_m > 0.0 && eye_height_m < 100.0)) {
    return "eye_height_m must be in (0, 100)";
  }
  if (!(pitch_down_deg > -80.0 && pitch_down_deg < 80.0)) {
    return "pitch_down_deg must be in (-80, 80)";
  }
  if (!(fov_deg >= 10.0 && fov_deg <= 120.0)) {
    return "fov_deg must be in [10, 120]";
  }
  if (!(min_stretch_m >= 0.0 && std::isfinite(min_stretch_m))) {
    return "min_stretch_m must be >= 0";
  }
  if (!(ceiling_cut_m > 0.0 && std::isfinite(ceiling_cut_m))) {
    return "ceiling_cut_m must be > 0";
  }
  if (!(footprint_px >= 1.0 && footprint_px <= 50.0)) {
    return "footprint_px must be in [1, 50]";
  }
  return {};
}

Eigen::Vector3d OrbitCamera::eye() const {
  const double az = azimuth_deg * kDeg, el = elevation_deg * kDeg;
  return target + distance_m * Eigen::Vector3d(std::cos(az) * std::cos(el),
                                               std::sin(az) * std::cos(el), std::sin(el));
}

PathStretch longestStraightStretch(const std::vector<Eigen::Vector3d>& path) {
  const std::vector<Eigen::Vector3d> p = resample(path);
  PathStretch best;
  for (std::size_t i = 0; i + 1 < p.size(); ++i) {
    std::size_t j = i + 1;
    while (j + 1 < p.size() && j + 1 - i <= kMaxRunSamples && straight(p, i, j + 1)) {
      ++j;
    }
    const double length = (xy(p[j]) - xy(p[i])).norm();
    if (length > best.length_m + 1e-9) {
      best = {p[i], p[j], length};
    }
  }
  return best;
}

double floorHeight(const products::MapModel& model) {
  std::vector<double> z;
  for (const auto& p : model.path) {
    if (std::isfinite(p.z())) {
      z.push_back(p.z());
    }
  }
  if (!z.empty()) {
    std::nth_element(z.begin(), z.begin() + static_cast<std::ptrdiff_t>(z.size() / 2), z.end());
    return z[z.size() / 2];
  }
  const Eigen::AlignedBox3d box = mapBox(model);
  return box.isEmpty() ? 0.0 : box.min().z();
}

Eigen::AlignedBox3d mapBox(const products::MapModel& model) {
  Eigen::AlignedBox3d box;
  const auto add = [&box](const Eigen::Vector3d& p) {
    if (p.allFinite()) {
      box.extend(p);
    }
  };
  for (const auto& q : model.quads) {
    std::for_each(q.corners.begin(), q.corners.end(), add);
  }
  std::for_each(model.fine.vertices.begin(), model.fine.vertices.end(), add);
  std::for_each(model.path.begin(), model.path.end(), add);
  return box;
}

PerspectiveView perspectiveView(const products::MapModel& model, const Eigen::AlignedBox3d& box,
                                const MapViewOptions& o) {
  PerspectiveView view;
  view.stretch = longestStraightStretch(model.path);
  const PathStretch& stretch = view.stretch;
  if (stretch.length_m < std::max(o.min_stretch_m, 1e-6)) {
    const Eigen::Vector3d zero = Eigen::Vector3d::Zero();
    view.camera = threeQuarterCamera(box.isEmpty() ? Eigen::AlignedBox3d(zero, zero) : box, o);
    return view;
  }
  const Eigen::Vector2d d = (xy(stretch.end) - xy(stretch.start)).normalized();
  const double el = o.pitch_down_deg * kDeg;
  const Eigen::Vector3d eye = stretch.start + Eigen::Vector3d(0, 0, o.eye_height_m);
  OrbitCamera c;
  c.distance_m = 1.0;
  c.azimuth_deg = std::atan2(-d.y(), -d.x()) / kDeg;
  c.elevation_deg = o.pitch_down_deg;
  c.target = eye - Eigen::Vector3d(-d.x() * std::cos(el), -d.y() * std::cos(el), std::sin(el));
  c.fov_deg = o.fov_deg;
  view.camera = c;
  view.on_path = true;
  return view;
}

OrbitCamera topCamera(const Eigen::AlignedBox3d& box_in, const MapViewOptions& o) {
  const Eigen::AlignedBox3d box =
      box_in.isEmpty() ? Eigen::AlignedBox3d(Eigen::Vector3d(-5, -5, 0), Eigen::Vector3d(5, 5, 0))
                       : box_in;
  const double r = aspect(o);
  const double w = std::max(1.0, 1.05 * box.sizes().x());
  const double h = std::max(1.0, 1.05 * box.sizes().y());
  OrbitCamera c;
  c.orthographic = true;
  c.target = Eigen::Vector3d(box.center().x(), box.center().y(), box.max().z());
  c.azimuth_deg = -90;
  c.elevation_deg = 90;
  c.distance_m = 2.0 * std::max(w / std::max(r, 1.0), h / std::max(1.0 / r, 1.0));
  return c;
}

double topMetresPerPixel(const OrbitCamera& camera, const MapViewOptions& o) {
  const double r = aspect(o);
  const double full_height = 0.5 * camera.distance_m * std::max(1.0 / r, 1.0);
  return full_height / o.height_px;
}

}  // namespace pmap::report
