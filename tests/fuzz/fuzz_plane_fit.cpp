// libFuzzer target: bytes -> points -> the plane / rectangle fit and a short
// offline EM (two iterations, small caps). Byte 0 picks the scale and the
// offset from the origin (up to 1e6 m), then each 6 bytes are one point
// (three int16). Checks: unit normals, finite rectangles, one assignment per
// point; any crash or sanitizer report is a finding.
#include <cmath>
#include <cstring>
#include <vector>

#include "fuzz_support.h"
#include "pmap/em/neighbours.h"
#include "pmap/em/offline_em.h"
#include "pmap/em/surface_fit.h"

namespace {

constexpr std::size_t kMaxPoints = 600;  // keeps an execution in milliseconds

std::vector<Eigen::Vector3d> decodePoints(const std::uint8_t* data, std::size_t size) {
  const double scales[] = {1e-6, 1e-3, 1e-2, 1.0};
  const double offsets[] = {0.0, 1.0, 1e3, 1e6};
  const double scale = scales[data[0] & 3];
  const double offset = offsets[(data[0] >> 2) & 3];
  std::vector<Eigen::Vector3d> points;
  for (std::size_t at = 1; at + 6 <= size && points.size() < kMaxPoints; at += 6) {
    std::int16_t v[3];
    std::memcpy(v, data + at, 6);
    points.emplace_back(offset + scale * v[0], scale * v[1], offset + scale * v[2]);
  }
  return points;
}

void checkRectangle(const pmap::em::Rectangle& r) {
  if (!r.normal.allFinite() || std::abs(r.normal.norm() - 1.0) > 1e-6) {
    pmap::fuzz::invariantFailed("normal is not a finite unit vector");
  }
  if (!r.centre.allFinite() || !(r.half_u >= 0.0) || !(r.half_v >= 0.0)) {
    pmap::fuzz::invariantFailed("rectangle is not finite");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) {
    return 0;
  }
  const std::vector<Eigen::Vector3d> points = decodePoints(data, size);
  std::vector<std::int32_t> members(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    members[i] = static_cast<std::int32_t>(i);
  }
  pmap::em::Rectangle rect;
  if (pmap::em::fitSurface(points, members, rect) == pmap::em::FitStatus::kOk) {
    checkRectangle(rect);
  }

  // One short EM over the points as a 30-column grid (rows = scans).
  std::vector<pmap::em::GridKey> keys(points.size());
  std::vector<std::int32_t> rows(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    rows[i] = static_cast<std::int32_t>(i / 30);
    keys[i] = {0, rows[i], static_cast<std::int32_t>(i % 30)};
  }
  pmap::em::PlanarEmOptions options;
  options.max_iterations = 2;
  options.selection_interval = 1;
  options.min_support = 10;
  options.min_rows = 2;
  const pmap::em::EmResult result =
      pmap::em::OfflineEm(options).run(points, pmap::em::gridNeighbours(keys), rows);
  if (result.map.assignment.size() != points.size()) {
    pmap::fuzz::invariantFailed("not one assignment per point");
  }
  for (const auto& s : result.map.surfaces) {
    checkRectangle(s.rect);
  }
  return 0;
}
