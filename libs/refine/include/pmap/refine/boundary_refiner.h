// Joint refinement of planes and rectangle boundaries with Ceres: adjacent
// non-parallel rectangles end on their planes' intersection line (seams.h)
// while staying faithful to the measurements (eq. 5 with a robust loss) and
// to the points' extent; optionally a Manhattan prior. Parallel neighbours
// (a recessed door and its wall) never share a seam and keep their planes.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "pmap/em/responsibilities.h"
#include "pmap/em/surface.h"
#include "pmap/refine/refine_options.h"
#include "pmap/refine/seams.h"

namespace pmap::refine {

struct BoundaryResult {
  std::string termination;  ///< Ceres' termination type, or "nothing to refine"
  int iterations = 0;
  double initial_cost = 0;  ///< Ceres cost (half the sum of squared scaled residuals)
  double final_cost = 0;
  std::vector<Seam> seams;  ///< as found before the solve
  std::size_t manhattan_pairs = 0;
  /// Surfaces that kept the EM's geometry (the solve would have turned the
  /// normal too far or collapsed the rectangle), by id.
  std::vector<std::int32_t> reverted_ids;
  bool usable() const { return termination != "FAILURE"; }
};

/// A measurement of a surface, its expectation e_ij (eq. 17) and whether the
/// surface is its most likely cause.
struct SurfaceSample {
  std::int32_t point = 0;
  double weight = 1.0;
  bool member = true;
};

/// Per surface its measurements with e_ij >= min_weight, from an E-step.
std::vector<std::vector<SurfaceSample>> samplesFromResponsibilities(
    const em::Responsibilities& resp, std::size_t surfaces, double min_weight = 0.01);

/// Refines `surfaces` in place from `samples[j]`, the measurements of
/// surface j with their expectations. As in the M-step, the plane follows
/// the soft weights (eqs. 24-27: at the EM's fixed point a surface that meets
/// nothing keeps its plane) and the rectangle the members, the measurements
/// whose most likely cause it is (eq. 29). `sigma_m` is the EM's.
BoundaryResult refineBoundaries(const std::vector<Eigen::Vector3d>& points,
                                const std::vector<std::vector<SurfaceSample>>& samples,
                                double sigma_m, const RefineOptions& options,
                                std::vector<em::Surface>& surfaces);

}  // namespace pmap::refine
