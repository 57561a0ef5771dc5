#include "pmap/sim/renderer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "pmap/sim/surface_textures.h"

namespace pmap::sim {
namespace {

constexpr double kNear_m = 0.02;
/// Sample offsets (pixels) of the 2 x 2 area integration of poster pixels.
constexpr std::pair<double, double> kSubpixelOffsets[4] = {
    {-0.25, -0.25}, {0.25, -0.25}, {-0.25, 0.25}, {0.25, 0.25}};
const cv::Vec3f kBackground(20.0f, 20.0f, 20.0f);

struct PixelBox {
  int u0 = 0, u1 = -1, v0 = 0, v1 = -1;
  bool empty() const { return u1 < u0 || v1 < v0; }
};

/// Clips a polygon (optical frame) to z >= near (Sutherland-Hodgman, one plane).
std::vector<Eigen::Vector3d> clipNear(const std::vector<Eigen::Vector3d>& poly) {
  std::vector<Eigen::Vector3d> out;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Eigen::Vector3d& a = poly[i];
    const Eigen::Vector3d& b = poly[(i + 1) % poly.size()];
    const bool a_in = a.z() >= kNear_m;
    const bool b_in = b.z() >= kNear_m;
    if (a_in) {
      out.push_back(a);
    }
    if (a_in != b_in) {
      const double t = (kNear_m - a.z()) / (b.z() - a.z());
      out.push_back(a + t * (b - a));
    }
  }
  return out;
}

PixelBox boundingBox(const PinholeIntrinsics& k, const std::vector<Eigen::Vector3d>& poly_cam) {
  PixelBox box;
  if (poly_cam.empty()) {
    return box;
  }
  double umin = std::numeric_limits<double>::infinity(), vmin = umin;
  double umax = -umin, vmax = -umin;
  for (const Eigen::Vector3d& p : poly_cam) {
    const double u = k.cx + k.fx * p.x() / p.z();
    const double v = k.cy + k.fy * p.y() / p.z();
    umin = std::min(umin, u);
    umax = std::max(umax, u);
    vmin = std::min(vmin, v);
    vmax = std::max(vmax, v);
  }
  box.u0 = static_cast<int>(std::max(0.0, std::floor(umin)));
  box.u1 = static_cast<int>(std::min(k.width_px - 1.0, std::ceil(umax)));
  box.v0 = static_cast<int>(std::max(0.0, std::floor(vmin)));
  box.v1 = static_cast<int>(std::min(k.height_px - 1.0, std::ceil(vmax)));
  return box;
}

float shading(const Eigen::Vector3d& normal, const Eigen::Vector3d& ray, double depth) {
  const double facing = std::abs(normal.dot(ray)) / ray.norm();
  return static_cast<float>((0.45 + 0.55 * facing) / (1.0 + 0.015 * depth));
}

cv::Vec3f toVec(const Eigen::Vector3f& c) {
  return cv::Vec3f(c.x(), c.y(), c.z());
}

Eigen::Vector3f samplePoster(const cv::Mat& img, const Poster& p, const Eigen::Vector2d& local) {
  const double col = std::clamp(local.x() * p.pixels_per_m - 0.5, 0.0, img.cols - 1.0);
  const double row =
      std::clamp((p.rect.length_v - local.y()) * p.pixels_per_m - 0.5, 0.0, img.rows - 1.0);
  const int c0 = static_cast<int>(col);
  const int r0 = static_cast<int>(row);
  const int c1 = std::min(c0 + 1, img.cols - 1);
  const int r1 = std::min(r0 + 1, img.rows - 1);
  const float fc = static_cast<float>(col - c0);
  const float fr = static_cast<float>(row - r0);
  Eigen::Vector3f out;
  for (int ch = 0; ch < 3; ++ch) {
    const float a = img.at<cv::Vec3b>(r0, c0)[ch], b = img.at<cv::Vec3b>(r0, c1)[ch];
    const float c = img.at<cv::Vec3b>(r1, c0)[ch], d = img.at<cv::Vec3b>(r1, c1)[ch];
    out[ch] = (a + (b - a) * fc) * (1.0f - fr) + (c + (d - c) * fc) * fr;
  }
  return out;
}

}  // namespace

struct Renderer::Frame {
  const PinholeIntrinsics& k;
  const RigidTransform& cam;
  cv::Mat colour;  ///< CV_32FC3
  cv::Mat depth;   ///< CV_64FC1
};

Renderer::Renderer(const World& world, const std::vector<cv::Mat>& poster_images,
                   std::uint32_t texture_seed)
    : world_(world), posters_(poster_images), texture_seed_(texture_seed) {}

Eigen::Vector3f Renderer::surfaceColour(const Surface& s, const Eigen::Vector3d& p_world,
                                        const Eigen::Vector2d& local) const {
  for (const int pi : s.poster_indices) {
    const Poster& p = world_.posters[static_cast<std::size_t>(pi)];
    const Eigen::Vector2d pl = p.rect.toLocal(p_world);
    if (pl.x() >= 0.0 && pl.x() <= p.rect.length_u && pl.y() >= 0.0 && pl.y() <= p.rect.length_v) {
      return samplePoster(posters_[static_cast<std::size_t>(pi)], p, pl);
    }
  }
  const auto variant = texture_seed_ + static_cast<std::uint32_t>(s.id) * 7919u;
  return materialColour(materialForSurfaceKind(s.kind), local.x(), local.y(), variant);
}

bool Renderer::nearPoster(const Surface& s, const Eigen::Vector3d& p_world, double margin_m) const {
  for (const int pi : s.poster_indices) {
    const Poster& p = world_.posters[static_cast<std::size_t>(pi)];
    const Eigen::Vector2d pl = p.rect.toLocal(p_world);
    if (pl.x() >= -margin_m && pl.x() <= p.rect.length_u + margin_m && pl.y() >= -margin_m &&
        pl.y() <= p.rect.length_v + margin_m) {
      return true;
    }
  }
  return false;
}

void Renderer::drawSurface(const Surface& s, Frame& f) const {
  std::vector<Eigen::Vector3d> poly;
  for (const Eigen::Vector3d& c : s.rect.corners()) {
    poly.push_back(f.cam.applyInverse(c));
  }
  const PixelBox box = boundingBox(f.k, clipNear(poly));
  if (box.empty()) {
    return;
  }
  const Eigen::Vector3d o = f.cam.applyInverse(s.rect.origin);
  const Eigen::Vector3d au = f.cam.rotation.transpose() * s.rect.axis_u;
  const Eigen::Vector3d av = f.cam.rotation.transpose() * s.rect.axis_v;
  const Eigen::Vector3d n = au.cross(av);
  const double n_dot_o = n.dot(o);
  for (int v = box.v0; v <= box.v1; ++v) {
    auto* depth = f.depth.ptr<double>(v);
    auto* colour = f.colour.ptr<cv::Vec3f>(v);
    for (int u = box.u0; u <= box.u1; ++u) {
      const Eigen::Vector3d ray = pixelRay(f.k, u, v);
      const double denom = n.dot(ray);
      if (std::abs(denom) < 1e-12) {
        continue;
      }
      const double t = n_dot_o / denom;  // = depth, since ray.z() == 1
      if (t < kNear_m || t >= depth[u]) {
        continue;
      }
      const Eigen::Vector3d d = t * ray - o;
      const Eigen::Vector2d local(d.dot(au), d.dot(av));
      if (!s.rect.containsLocal(local.x(), local.y())) {
        continue;
      }
      depth[u] = t;
      const Eigen::Vector3d p_world = f.cam.apply(t * ray);
      Eigen::Vector3f c = surfaceColour(s, p_world, local);
      if (nearPoster(s, p_world, 2.0 * t / f.k.fx)) {
        // Posters carry detail at the pixel scale: integrate the pixel's area
        // (2 x 2 samples) as a sensor pixel does, instead of point sampling.
        c.setZero();
        for (const auto& [du, dv] : kSubpixelOffsets) {
          const Eigen::Vector3d sub = pixelRay(f.k, u + du, v + dv);
          const Eigen::Vector3d q = (n_dot_o / n.dot(sub)) * sub;
          const Eigen::Vector3d dq = q - o;
          c += 0.25f * surfaceColour(s, f.cam.apply(q), Eigen::Vector2d(dq.dot(au), dq.dot(av)));
        }
      }
      colour[u] = toVec(c * shading(n, ray, t));
    }
  }
}

void Renderer::drawClutter(const Clutter& c, Frame& f) const {
  const bool cyl = c.shape == ClutterShape::kCylinder;
  const Eigen::Vector2d centre = cyl ? c.cylinder.centre : c.box.centre;
  const double r = cyl ? c.cylinder.radius_m : c.box.half_size_m.norm();
  const double z0 = cyl ? c.cylinder.z_min_m : c.box.z_min_m;
  const double z1 = cyl ? c.cylinder.z_max_m : c.box.z_max_m;
  std::vector<Eigen::Vector3d> corners;
  bool behind = false;
  for (int i = 0; i < 8; ++i) {
    const Eigen::Vector3d w(centre.x() + ((i & 1) ? r : -r), centre.y() + ((i & 2) ? r : -r),
                            (i & 4) ? z1 : z0);
    corners.push_back(f.cam.applyInverse(w));
    behind = behind || corners.back().z() < kNear_m;
  }
  PixelBox box = boundingBox(f.k, corners);
  if (behind) {
    box = PixelBox{0, f.k.width_px - 1, 0, f.k.height_px - 1};
  }
  const auto variant = texture_seed_ + static_cast<std::uint32_t>(c.id) * 7919u;
  const Material material = materialForClutterKind(c.kind);
  for (int v = box.v0; v <= box.v1; ++v) {
    for (int u = box.u0; u <= box.u1; ++u) {
      double& depth = f.depth.at<double>(v, u);
      const Eigen::Vector3d ray = pixelRay(f.k, u, v);
      const Eigen::Vector3d dir = f.cam.rotation * ray;
      const auto hit = cyl ? intersectCylinder(c.cylinder, f.cam.translation, dir, kNear_m, depth)
                           : intersectBox(c.box, f.cam.translation, dir, kNear_m, depth);
      if (!hit || hit->t >= depth) {
        continue;
      }
      depth = hit->t;
      const Eigen::Vector3f col = materialColour(material, hit->local.x(), hit->local.y(), variant);
      f.colour.at<cv::Vec3f>(v, u) = toVec(col * shading(hit->normal, dir, hit->t));
    }
  }
}

cv::Mat Renderer::render(const PinholeIntrinsics& k, const RigidTransform& camera_to_world) const {
  Frame f{k, camera_to_world, cv::Mat(k.height_px, k.width_px, CV_32FC3, kBackground),
          cv::Mat(k.height_px, k.width_px, CV_64FC1,
                  cv::Scalar(std::numeric_limits<double>::infinity()))};
  for (const Surface& s : world_.surfaces) {
    if (s.kind != "glass") {  // clear glass: the camera sees what lies behind it
      drawSurface(s, f);
    }
  }
  for (const Clutter& c : world_.clutter) {
    drawClutter(c, f);
  }
  return f.colour;
}

}  // namespace pmap::sim
