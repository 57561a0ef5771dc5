#include "pmap/viewer/point_subsample.h"

#include <cstring>

namespace pmap::viewer {

std::vector<Eigen::Vector3f> subsamplePoints(const std::vector<Eigen::Vector3f>& points,
                                             std::size_t max_points) {
  std::vector<Eigen::Vector3f> finite;
  finite.reserve(points.size());
  for (const Eigen::Vector3f& p : points) {
    if (p.allFinite()) {
      finite.push_back(p);
    }
  }
  if (finite.size() <= max_points) {
    return finite;
  }
  if (max_points == 0) {
    return {};
  }
  const std::size_t stride = (finite.size() + max_points - 1) / max_points;
  std::vector<Eigen::Vector3f> kept;
  kept.reserve(max_points);
  for (std::size_t i = 0; i < finite.size(); i += stride) {
    kept.push_back(finite[i]);
  }
  return kept;
}

std::vector<std::uint8_t> packFloat32(const std::vector<Eigen::Vector3f>& points) {
  static_assert(sizeof(float) == 4, "float32 expected");
  std::vector<std::uint8_t> bytes(points.size() * 12);
  std::uint8_t* out = bytes.data();
  for (const Eigen::Vector3f& p : points) {
    for (int axis = 0; axis < 3; ++axis) {
      std::uint32_t bits = 0;
      std::memcpy(&bits, &p[axis], 4);
      for (int b = 0; b < 4; ++b) {
        *out++ = static_cast<std::uint8_t>(bits >> (8 * b));
      }
    }
  }
  return bytes;
}

}  // namespace pmap::viewer
