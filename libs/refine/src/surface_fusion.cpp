#include "pmap/refine/surface_fusion.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <iterator>
#include <set>

#include "pmap/em/model_selector.h"

namespace pmap::refine {
namespace {

constexpr int kMaxPasses = 4;

std::set<std::int32_t> idsOf(const std::vector<em::Surface>& surfaces) {
  std::set<std::int32_t> ids;
  for (const em::Surface& s : surfaces) {
    ids.insert(s.id);
  }
  return ids;
}

// Ids in `a` and not in `b`, ascending.
std::vector<std::int32_t> missingFrom(const std::set<std::int32_t>& a,
                                      const std::set<std::int32_t>& b) {
  std::vector<std::int32_t> out;
  std::set_difference(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(out));
  return out;
}

}  // namespace

em::PlanarEmOptions fusionOptions(const em::PlanarEmOptions& em, const RefineOptions& options) {
  em::PlanarEmOptions o = em;
  o.fuse_offset_m = options.fuse_sigmas * em.sigma_m;
  o.fuse_angle_deg = std::atan(options.fuse_sigmas * em.sigma_m / 1.0) * 180.0 / M_PI;
  return o;
}

FusionResult fuseSurfaces(const std::vector<Eigen::Vector3d>& points,
                          const em::Neighbours& neighbours, const std::vector<std::int32_t>& rows,
                          const em::PlanarEmOptions& em, const RefineOptions& options,
                          em::PlanarMap& map) {
  assert(neighbours.size() == points.size());
  FusionResult result;
  if (map.surfaces.size() < 2) {
    return result;
  }
  const em::PlanarEmOptions o = fusionOptions(em, options);
  em::ModelSelector selector(points, neighbours, rows, o);
  std::int32_t next_id = 0;
  for (const em::Surface& s : map.surfaces) {
    next_id = std::max(next_id, s.id + 1);
  }
  std::vector<em::Surface> surfaces = map.surfaces;
  const std::set<std::int32_t> before = idsOf(surfaces);
  em::Responsibilities resp;
  result.changed_pairs = selector.fuse(surfaces, next_id, kMaxPasses, resp);
  if (result.changed_pairs > 0) {
    const std::set<std::int32_t> after = idsOf(surfaces);
    result.replaced_ids = missingFrom(before, after);
    result.new_ids = missingFrom(after, before);
    map = em::finalizeMap(points, neighbours, std::move(surfaces), resp, o);
  }
  return result;
}

}  // namespace pmap::refine
