// Fusion at the end of the EM (the paper's termination step, eq. 30):
// surfaces that are the same physical plane are fused when that raises the
// log posterior, and the fused rectangle is refit. The test itself is the
// EM's (em::ModelSelector::fuse); the tolerances here derive from sigma.
#pragma once

#include <cstdint>
#include <vector>

#include "pmap/em/neighbours.h"
#include "pmap/em/offline_em.h"
#include "pmap/em/planar_em_options.h"
#include "pmap/refine/refine_options.h"

namespace pmap::refine {

struct FusionResult {
  int changed_pairs = 0;                   ///< pairs fused (or re-cut, see ModelSelector)
  std::vector<std::int32_t> replaced_ids;  ///< surfaces that are gone
  std::vector<std::int32_t> new_ids;       ///< the surfaces that replaced them
};

/// The EM options the fusion test uses: fuse_offset_m = fuse_sigmas *
/// sigma, fuse_angle_deg = atan(fuse_sigmas * sigma / 1 m).
em::PlanarEmOptions fusionOptions(const em::PlanarEmOptions& em, const RefineOptions& options);

/// Fuses pairs of `map` (until no pair changes, at most a few passes);
/// recomputes the map's assignment, explained fraction and fine triangles
/// when anything changed. `rows` may be empty.
FusionResult fuseSurfaces(const std::vector<Eigen::Vector3d>& points,
                          const em::Neighbours& neighbours, const std::vector<std::int32_t>& rows,
                          const em::PlanarEmOptions& em, const RefineOptions& options,
                          em::PlanarMap& map);

}  // namespace pmap::refine
