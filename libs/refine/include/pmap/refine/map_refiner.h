// The refinement stage after the EM (offline or online): fusion of surfaces
// that are the same plane (surface_fusion.h), then the joint refinement of
// planes and boundaries (boundary_refiner.h). doc/refinement.md.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "pmap/em/neighbours.h"
#include "pmap/em/offline_em.h"
#include "pmap/em/planar_em_options.h"
#include "pmap/refine/boundary_refiner.h"
#include "pmap/refine/openings.h"
#include "pmap/refine/refine_options.h"
#include "pmap/refine/surface_fusion.h"

namespace pmap::refine {

struct RefineResult {
  bool ran = false;  ///< false: disabled, or no surfaces
  FusionResult fusion;
  BoundaryResult boundaries;
  OpeningResult openings;  ///< doors placed on their walls' openings
  double fusion_s = 0;     ///< wall time of the fusion step
  double solve_s = 0;      ///< wall time of the Ceres refinement
  std::string message;
};

/// Refines `map` in place. `options` and `em` must validate; `rows` may be
/// empty; `viewpoints` holds each point's sensor origin (empty: doors are not
/// placed on openings). Same input and options give the same map.
RefineResult refineMap(const std::vector<Eigen::Vector3d>& points, const em::Neighbours& neighbours,
                       const std::vector<std::int32_t>& rows, const em::PlanarEmOptions& em,
                       const RefineOptions& options, em::PlanarMap& map,
                       const std::vector<Eigen::Vector3d>& viewpoints = {});

}  // namespace pmap::refine
