// The offline EM planar mapper (sections II-IV): alternates the E-step
// (eqs. 17-18) and the M-step (eqs. 19-29) over all measurements, with model
// selection (eq. 30) every `selection_interval` iterations, until converged:
// no model-selection change in the last round and a relative change of the
// log posterior below `convergence_tolerance` for `convergence_patience`
// iterations in a row.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "pmap/em/fine_triangles.h"
#include "pmap/em/model_selector.h"
#include "pmap/em/neighbours.h"
#include "pmap/em/planar_em_options.h"
#include "pmap/em/surface.h"

namespace pmap::em {

struct IterationRecord {
  int iteration = 0;
  int surfaces = 0;
  double explained_fraction = 0.0;  ///< share of points whose most likely cause is a surface
  double log_posterior = 0.0;       ///< of the map entering this iteration (eq. 30)
  double log_likelihood = 0.0;      ///< sum_i l_i (prior held fixed)
  std::size_t points = 0;           ///< measurements it ran on (a sample: coarse-to-fine)
  SelectionChanges changes;         ///< model selection made before this iteration's E-step
};

/// How the offline EM ended (the online EM has no end: OnlineResult).
enum class Termination { kConverged, kMaxIterations, kNoPoints };
const char* toString(Termination t);

struct PlanarMap {
  std::vector<Surface> surfaces;
  std::vector<std::int32_t> assignment;  ///< per point: index into surfaces, -1 = outlier class
  std::vector<Triangle> fine_triangles;  ///< over outlier points
  double explained_fraction = 0.0;
};

struct EmResult {
  PlanarMap map;
  Termination termination = Termination::kNoPoints;
  int iterations = 0;
  /// In spatial blocks: each block's last record, in block order.
  std::vector<IterationRecord> history;
  std::string message;
  int blocks = 0;              ///< spatial blocks mapped (0: one run on all points)
  int blocks_unconverged = 0;  ///< ... of which stopped at max_iterations
};

class OfflineEm {
 public:
  /// `options` must validate.
  explicit OfflineEm(const PlanarEmOptions& options);

  /// Maps `points` (finite). `initial` surfaces start the EM (none: all from
  /// seeding). Same input, options and seed give the same map whatever
  /// options.threads is. More than 2 x coarse_points points: coarse to fine
  /// (model selection on a sample, planar_em_options.h).
  /// `rows` (may be empty): each point's row (scan), for the min_rows test.
  /// More than 2 x block_points points and no `initial` surfaces: in
  /// spatial blocks (spatial_blocks.h).
  EmResult run(const std::vector<Eigen::Vector3d>& points, const Neighbours& neighbours,
               const std::vector<std::int32_t>& rows, std::vector<Surface> initial = {}) const;

  /// Most iterations a run on `points` points makes: max_iterations, plus
  /// fine_iterations coarse to fine; in blocks, the number of blocks (the
  /// observer is called once per block mapped, from the thread that mapped it).
  int iterationCap(std::size_t points) const;

  /// Whether a run on `points` points (and no initial surfaces) is in
  /// spatial blocks.
  bool inBlocks(std::size_t points) const;

  /// Called after every iteration's E-step (progress lines); no effect on the map.
  void setObserver(std::function<void(const IterationRecord&)> observer) {
    observer_ = std::move(observer);
  }

 private:
  bool coarseToFine(std::size_t points) const;
  EmResult runInBlocks(const std::vector<Eigen::Vector3d>& points, const Neighbours& neighbours,
                       const std::vector<std::int32_t>& rows) const;
  /// EM iterations on `points` (those of `selector`) until converged or
  /// max_iterations, appended to `result` (iterations, history,
  /// termination); with `with_selection`, a model-selection round every
  /// selection_interval iterations.
  void iterate(const std::vector<Eigen::Vector3d>& points, const Neighbours& neighbours,
               const PlanarEmOptions& options, ModelSelector& selector, bool with_selection,
               std::vector<Surface>& surfaces, EmResult& result) const;

  PlanarEmOptions options_;
  std::function<void(const IterationRecord&)> observer_;
};

/// The final assignment, explained fraction and fine triangles of `surfaces`.
PlanarMap finalizeMap(const std::vector<Eigen::Vector3d>& points, const Neighbours& neighbours,
                      std::vector<Surface> surfaces, const ModelSelector& selector,
                      const PlanarEmOptions& options);
/// ... from their responsibilities `resp` over `points`, computed already.
PlanarMap finalizeMap(const std::vector<Eigen::Vector3d>& points, const Neighbours& neighbours,
                      std::vector<Surface> surfaces, const Responsibilities& resp,
                      const PlanarEmOptions& options);

}  // namespace pmap::em
