// Model selection, new surfaces (section IV-C): seeded from three adjacent
// poorly explained measurements (e_i* above a threshold), which fix the
// initial plane, chosen at random (seeded) among the candidates and capped
// per round. Beyond the paper, a seed is grown at once over the neighbour
// graph (poorly explained points within 2.5 sigma of the plane, the plane
// refitted as the region doubles), so a new wall starts at its full extent
// instead of creeping outwards a few centimetres per EM iteration.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <random>
#include <vector>

#include "pmap/em/measurement_model.h"
#include "pmap/em/neighbours.h"
#include "pmap/em/planar_em_options.h"
#include "pmap/em/surface.h"

namespace pmap::em {

struct SeedResult {
  std::vector<Rectangle> surfaces;                 ///< accepted new surfaces
  std::vector<std::vector<std::int32_t>> members;  ///< their grown points
  std::size_t candidates = 0;                      ///< seed triples available
  std::size_t attempts = 0;                        ///< seeds grown
};

/// Fits a surface to grown points and says whether to keep it.
using SurfaceCheck = std::function<bool(const std::vector<std::int32_t>&, Rectangle&)>;

/// Seeds new surfaces among points with outlier[i] > options.seed_outlier_probability;
/// `accept` fits each grown region and decides.
SeedResult seedSurfaces(const std::vector<Eigen::Vector3d>& points, const Neighbours& neighbours,
                        const std::vector<double>& outlier, const MeasurementModel& model,
                        const PlanarEmOptions& options, const SurfaceCheck& accept,
                        std::mt19937_64& rng, std::size_t max_attempts = 0);

}  // namespace pmap::em
