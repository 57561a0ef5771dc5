#include "pmap/products/map_model_check.h"

#include <set>
#include <stdexcept>
#include <string>
#include <utility>

namespace pmap::products {
namespace {

[[noreturn]] void fail(const std::string& what) {
  throw std::invalid_argument("MapModel: " + what);
}

using SurfaceTile = std::pair<std::int32_t, std::int32_t>;

void checkQuad(const TexturedQuad& q, std::size_t index, std::set<SurfaceTile>& ids) {
  const std::string name = "quad " + std::to_string(index) + " (surface " +
                           std::to_string(q.surface_id) + ", tile " + std::to_string(q.tile) + ")";
  for (const Eigen::Vector3d& c : q.corners) {
    if (!c.allFinite()) {
      fail(name + ": non-finite corner");
    }
  }
  if (!q.normal.allFinite() || q.normal.norm() == 0.0) {
    fail(name + ": normal must be finite and non-zero");
  }
  if (!q.color.allFinite()) {
    fail(name + ": non-finite colour");
  }
  if (q.surface_id >= 0 && !ids.insert({q.surface_id, q.tile}).second) {
    fail(name + ": duplicate (surface_id, tile)");
  }
  if (q.texture.empty()) {
    return;
  }
  if (q.surface_id < 0 || q.tile < 0) {
    fail(name + ": a textured quad needs surface_id >= 0 and tile >= 0 (they name its file)");
  }
  if (q.texture.type() != CV_8UC3) {
    fail(name + ": texture must be 8-bit BGR (CV_8UC3)");
  }
}

void checkFine(const ColoredTriangles& fine) {
  for (const Eigen::Vector3d& v : fine.vertices) {
    if (!v.allFinite()) {
      fail("fine triangles: non-finite vertex");
    }
  }
  for (const auto& t : fine.triangles) {
    for (const std::uint32_t i : t) {
      if (i >= fine.vertices.size()) {
        fail("fine triangles: vertex index " + std::to_string(i) + " out of range (" +
             std::to_string(fine.vertices.size()) + " vertices)");
      }
    }
  }
  if (!fine.colors.empty() && fine.colors.size() != fine.vertices.size()) {
    fail("fine triangles: " + std::to_string(fine.colors.size()) + " colours for " +
         std::to_string(fine.vertices.size()) + " vertices");
  }
  for (const Eigen::Vector3f& c : fine.colors) {
    if (!c.allFinite()) {
      fail("fine triangles: non-finite colour");
    }
  }
  if (!fine.color.allFinite()) {
    fail("fine triangles: non-finite colour");
  }
}

}  // namespace

void checkMapModel(const MapModel& model) {
  std::set<SurfaceTile> ids;
  for (std::size_t i = 0; i < model.quads.size(); ++i) {
    checkQuad(model.quads[i], i, ids);
  }
  checkFine(model.fine);
  for (const Eigen::Vector3d& p : model.path) {
    if (!p.allFinite()) {
      fail("path: non-finite position");
    }
  }
}

}  // namespace pmap::products
