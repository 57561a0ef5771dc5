#include "pmap/em/offline_em.h"

#include <atomic>
#include <cassert>
#include <cmath>
#include <exception>
#include <mutex>
#include <thread>

#include "pmap/em/model_selection.h"
#include "pmap/em/spatial_blocks.h"
#include "pmap/em/subsample.h"
#include "pmap/em/surface_fit.h"

namespace pmap::em {
namespace {

double explainedFraction(const Responsibilities& resp) {
  if (resp.points() == 0) {
    return 0.0;
  }
  std::size_t explained = 0;
  for (const std::int32_t b : resp.best) {
    explained += b >= 0 ? 1 : 0;
  }
  return static_cast<double>(explained) / static_cast<double>(resp.points());
}

std::vector<double> emptyAreas(const std::vector<Eigen::Vector3d>& points,
                               const Responsibilities& resp, const std::vector<Surface>& surfaces,
                               double cell_m) {
  const auto members = hardMembers(resp, surfaces.size());
  std::vector<double> out(surfaces.size());
  for (std::size_t j = 0; j < surfaces.size(); ++j) {
    out[j] = emptyArea(points, members[j], surfaces[j].rect, cell_m);
  }
  return out;
}

/// The first surface id above those of `surfaces` (0 if none).
std::int32_t nextFreeId(const std::vector<Surface>& surfaces) {
  std::int32_t next_id = 0;
  for (const Surface& s : surfaces) {
    next_id = std::max(next_id, s.id + 1);
  }
  return next_id;
}

}  // namespace

const char* toString(Termination t) {
  switch (t) {
    case Termination::kConverged:
      return "converged";
    case Termination::kMaxIterations:
      return "max_iterations";
    default:
      return "no_points";
  }
}

OfflineEm::OfflineEm(const PlanarEmOptions& options) : options_(options) {
  assert(options.validate(nullptr));
}

PlanarMap finalizeMap(const std::vector<Eigen::Vector3d>& points, const Neighbours& neighbours,
                      std::vector<Surface> surfaces, const ModelSelector& selector,
                      const PlanarEmOptions& options) {
  Responsibilities resp;
  selector.expect(surfaces, resp);
  return finalizeMap(points, neighbours, std::move(surfaces), resp, options);
}

PlanarMap finalizeMap(const std::vector<Eigen::Vector3d>& points, const Neighbours& neighbours,
                      std::vector<Surface> surfaces, const Responsibilities& resp,
                      const PlanarEmOptions& options) {
  const auto members = hardMembers(resp, surfaces.size());
  PlanarMap map;
  map.assignment = resp.best;
  map.explained_fraction = explainedFraction(resp);
  std::vector<char> outlier(points.size(), 0);
  for (std::size_t i = 0; i < points.size(); ++i) {
    outlier[i] = resp.best[i] < 0 ? 1 : 0;
  }
  map.fine_triangles =
      fineTriangles(points, neighbours, outlier, options.fine_max_edge_m, options.fine_cell_m);
  for (std::size_t j = 0; j < surfaces.size(); ++j) {
    surfaces[j].support = static_cast<std::int32_t>(members[j].size());
  }
  map.surfaces = std::move(surfaces);
  return map;
}

bool OfflineEm::inBlocks(std::size_t points) const {
  const auto block = static_cast<std::size_t>(options_.block_points);
  return block > 0 && points > 2 * block;
}

bool OfflineEm::coarseToFine(std::size_t points) const {
  const auto coarse = static_cast<std::size_t>(options_.coarse_points);
  return coarse > 0 && points > 2 * coarse;
}

int OfflineEm::iterationCap(std::size_t points) const {
  if (inBlocks(points)) {
    return static_cast<int>(blockCount(points, static_cast<std::size_t>(options_.block_points)));
  }
  return options_.max_iterations + (coarseToFine(points) ? options_.fine_iterations : 0);
}

EmResult OfflineEm::run(const std::vector<Eigen::Vector3d>& points, const Neighbours& neighbours,
                        const std::vector<std::int32_t>& rows,
                        std::vector<Surface> surfaces) const {
  EmResult result;
  if (points.empty()) {
    result.message = "no points";
    return result;
  }
  if (inBlocks(points.size()) && surfaces.empty()) {
    return runInBlocks(points, neighbours, rows);
  }
  if (coarseToFine(points.size())) {
    // Model selection on a sample, then E- and M-steps on all points.
    const Subsample sample = drawSubsample(
        points, neighbours, rows, static_cast<std::size_t>(options_.coarse_points), options_.seed);
    const PlanarEmOptions sampled = scaledToSample(options_, sample.fraction);
    ModelSelector on_sample(sample.points, sample.neighbours, sample.rows, sampled);
    iterate(sample.points, sample.neighbours, sampled, on_sample, true, surfaces, result);
    const Termination on_the_sample = result.termination;
    const int coarse_iterations = result.iterations;
    PlanarEmOptions fine = options_;
    fine.max_iterations = options_.fine_iterations;
    ModelSelector on_all(points, neighbours, rows, options_);
    iterate(points, neighbours, fine, on_all, false, surfaces, result);
    result.termination = on_the_sample;  // the fine phase is capped by design
    on_all.prune(surfaces);              // the full data's verdict
    result.map = finalizeMap(points, neighbours, std::move(surfaces), on_all, options_);
    result.message = std::string(toString(result.termination)) + " after " +
                     std::to_string(coarse_iterations) + " iterations on a sample of " +
                     std::to_string(sample.points.size()) + " points, then " +
                     std::to_string(result.iterations - coarse_iterations) + " on all, " +
                     std::to_string(result.map.surfaces.size()) + " surfaces";
    return result;
  }
  ModelSelector selector(points, neighbours, rows, options_);
  iterate(points, neighbours, options_, selector, true, surfaces, result);
  result.map = finalizeMap(points, neighbours, std::move(surfaces), selector, options_);
  result.message = std::string(toString(result.termination)) + " after " +
                   std::to_string(result.iterations) + " iterations, " +
                   std::to_string(result.map.surfaces.size()) + " surfaces";
  return result;
}

// Large inputs in spatial blocks (spatial_blocks.h): each block, with its
// margin, is mapped on its own (coarse to fine with block_coarse_points);
// a block keeps the surfaces that hold more of its own points than of its
// margin's (the others belong to a neighbour, which maps them with their
// own points). Then one E-step on all points gives the assignment and the
// fine triangles. A surface cut by a seam ends as two overlapping,
// coplanar pieces, which the refinement's fusion joins (surface_fusion.h).
EmResult OfflineEm::runInBlocks(const std::vector<Eigen::Vector3d>& points,
                                const Neighbours& neighbours,
                                const std::vector<std::int32_t>& rows) const {
  const std::vector<SpatialBlock> blocks = cutIntoBlocks(
      points, static_cast<std::size_t>(options_.block_points), options_.block_margin_m);
  PlanarEmOptions one = options_;
  one.block_points = 0;
  one.coarse_points = options_.block_coarse_points;
  one.threads = 1;  // the blocks run side by side instead
  std::vector<EmResult> done(blocks.size());
  std::atomic<std::size_t> next{0};
  std::mutex progress;  // the observer, `finished` and `failure`
  std::size_t finished = 0;
  std::exception_ptr failure;
  const auto work = [&]() {
    for (std::size_t b = next++; b < blocks.size(); b = next++) {
      try {
        const BlockInput in = blockInput(blocks[b], points, neighbours, rows);
        done[b] = OfflineEm(one).run(in.points, in.neighbours, in.rows);
      } catch (...) {  // rethrown on the caller's thread
        const std::lock_guard<std::mutex> lock(progress);
        failure = failure ? failure : std::current_exception();
        next = blocks.size();
        return;
      }
      const std::lock_guard<std::mutex> lock(progress);
      if (observer_) {
        IterationRecord rec = done[b].history.empty() ? IterationRecord{} : done[b].history.back();
        rec.iteration = static_cast<int>(finished);
        observer_(rec);
      }
      ++finished;
    }
  };
  const int threads = std::min<int>(options_.threads, static_cast<int>(blocks.size()));
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) {
    pool.emplace_back(work);
  }
  work();
  for (std::thread& t : pool) {
    t.join();
  }
  if (failure) {
    std::rethrow_exception(failure);
  }
  EmResult result;
  result.termination = Termination::kConverged;
  result.blocks = static_cast<int>(blocks.size());
  std::vector<Surface> surfaces;
  std::int32_t next_id = 0;
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    const EmResult& r = done[b];
    result.iterations += r.iterations;
    if (r.termination != Termination::kConverged) {
      result.termination = r.termination;
      ++result.blocks_unconverged;
    }
    if (!r.history.empty()) {
      result.history.push_back(r.history.back());
    }
    std::vector<std::size_t> own(r.map.surfaces.size(), 0), all(r.map.surfaces.size(), 0);
    for (std::size_t k = 0; k < r.map.assignment.size(); ++k) {
      const std::int32_t j = r.map.assignment[k];
      if (j >= 0) {
        ++all[static_cast<std::size_t>(j)];
        own[static_cast<std::size_t>(j)] += k < blocks[b].core ? 1 : 0;
      }
    }
    for (std::size_t j = 0; j < r.map.surfaces.size(); ++j) {
      if (2 * own[j] > all[j]) {
        surfaces.push_back(r.map.surfaces[j]);
        surfaces.back().id = next_id++;
      }
    }
  }
  Responsibilities resp;
  expectAll(points, surfaces, options_, resp);
  result.map = finalizeMap(points, neighbours, std::move(surfaces), resp, options_);
  result.message = std::string(toString(result.termination)) + " in " +
                   std::to_string(blocks.size()) + " blocks (" + std::to_string(result.iterations) +
                   " iterations in all), " + std::to_string(result.map.surfaces.size()) +
                   " surfaces";
  return result;
}

void OfflineEm::iterate(const std::vector<Eigen::Vector3d>& points, const Neighbours& neighbours,
                        const PlanarEmOptions& options, ModelSelector& selector,
                        bool with_selection, std::vector<Surface>& surfaces,
                        EmResult& result) const {
  const bool select = options.model_selection && with_selection;
  std::int32_t next_id = nextFreeId(surfaces);
  Responsibilities resp;
  int patience = 0;
  bool last_round_quiet = false;
  double previous = std::nan("");
  result.termination = Termination::kMaxIterations;
  for (int it = 0; it < options.max_iterations; ++it) {
    IterationRecord rec;
    rec.iteration = result.iterations;
    rec.points = points.size();
    if (select && it % options.selection_interval == 0) {
      rec.changes = selector.round(surfaces, next_id);
      last_round_quiet = !rec.changes.any() && it > 0;
      if (rec.changes.any()) {
        patience = 0;
      }
    }
    selector.expect(surfaces, resp);  // E-step, eqs. (17)-(18)
    rec.surfaces = static_cast<int>(surfaces.size());
    rec.explained_fraction = explainedFraction(resp);
    rec.log_likelihood = resp.total_loglik;
    rec.log_posterior = logPosterior(
        resp, surfaces, emptyAreas(points, resp, surfaces, options.split_cell_m), options);
    result.history.push_back(rec);
    result.iterations += 1;
    if (observer_) {
      observer_(rec);
    }
    const double change = std::abs(rec.log_posterior - previous);
    const bool small = change < options.convergence_tolerance * std::abs(previous) ||
                       change < options.convergence_absolute_nats;
    patience = small ? patience + 1 : 0;
    previous = rec.log_posterior;
    const bool selection_settled = !select || last_round_quiet;
    if (selection_settled && patience >= options.convergence_patience) {
      result.termination = Termination::kConverged;
      break;
    }
    maximizeSurfaces(points, neighbours, resp, options.threads, surfaces,
                     options.rules.coherent_neighbours);  // eqs. (19)-(29)
  }
  if (select && result.termination != Termination::kConverged) {
    selector.prune(surfaces);  // surfaces seeded in the last round were never re-checked
  }
}

}  // namespace pmap::em
