#include "pmap/refine/map_refiner.h"

#include <chrono>

#include "pmap/em/model_selector.h"

namespace pmap::refine {
namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

std::string describe(const RefineResult& r) {
  std::string m = std::to_string(r.fusion.changed_pairs) + " pairs fused, " +
                  std::to_string(r.boundaries.seams.size()) + " seams, " + r.boundaries.termination;
  if (!r.openings.openings.empty()) {
    m += ", " + std::to_string(r.openings.openings.size()) + " doors on their openings";
  }
  if (!r.boundaries.reverted_ids.empty()) {
    m += ", " + std::to_string(r.boundaries.reverted_ids.size()) + " surfaces kept unrefined";
  }
  return m;
}

}  // namespace

RefineResult refineMap(const std::vector<Eigen::Vector3d>& points, const em::Neighbours& neighbours,
                       const std::vector<std::int32_t>& rows, const em::PlanarEmOptions& em,
                       const RefineOptions& options, em::PlanarMap& map,
                       const std::vector<Eigen::Vector3d>& viewpoints) {
  RefineResult result;
  if (!options.enabled || map.surfaces.empty()) {
    result.message = options.enabled ? "no surfaces" : "disabled";
    return result;
  }
  result.ran = true;
  auto t0 = Clock::now();
  if (options.fuse) {
    result.fusion = fuseSurfaces(points, neighbours, rows, em, options, map);
  }
  result.fusion_s = since(t0);
  t0 = Clock::now();
  em::ModelSelector selector(points, neighbours, rows, em);
  em::Responsibilities resp;
  selector.expect(map.surfaces, resp);  // E-step, eqs. (17)-(18): the weights of the fit
  result.boundaries =
      refineBoundaries(points, samplesFromResponsibilities(resp, map.surfaces.size()), em.sigma_m,
                       options, map.surfaces);
  if (options.openings) {
    result.openings = alignToOpenings(points, resp.best, viewpoints, options, map.surfaces);
  }
  result.solve_s = since(t0);
  result.message = describe(result);
  return result;
}

}  // namespace pmap::refine
