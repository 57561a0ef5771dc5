// Micro-benchmarks of the EM's hot paths on a synthetic corridor
// (synthetic_corridor.h): the E-step per point-surface pair, the M-step per
// surface, the rectangle fit (eq. 29) and a model-selection round's coverage
// cut. Run by scripts/bench.sh.
#include <benchmark/benchmark.h>

#include "pmap/em/coverage_cut.h"
#include "pmap/em/measurement_model.h"
#include "pmap/em/planar_em_options.h"
#include "pmap/em/rectangle_index.h"
#include "pmap/em/responsibilities.h"
#include "pmap/em/split_proposals.h"
#include "pmap/em/surface_fit.h"
#include "synthetic_corridor.h"

namespace pmap::bench {
namespace {

struct EStepSetup {
  explicit EStepSetup(int scans)
      : corridor(makeCorridor(scans)),
        model(options.sigma_m, options.z_max_m),
        index(corridor.surfaces, model.cutoffDistance(options.responsibility_tolerance)) {}
  em::PlanarEmOptions options;
  Corridor corridor;
  em::MeasurementModel model;
  em::RectangleIndex index;
  em::Responsibilities resp;
  void run() {
    em::computeResponsibilities(corridor.points, corridor.surfaces, index, model,
                                options.responsibility_tolerance, 1, resp);
  }
};

// E-step, eqs. (17)-(18): items = point-surface pairs evaluated (the
// candidates within the cutoff), so the time per item is per pair.
void BM_EStep(benchmark::State& state) {
  EStepSetup s(static_cast<int>(state.range(0)));
  s.run();
  const auto pairs = static_cast<std::int64_t>(s.resp.surface.size());
  for (auto _ : state) {
    s.run();
    benchmark::DoNotOptimize(s.resp.total_loglik);
  }
  state.SetItemsProcessed(state.iterations() * pairs);
  state.counters["points"] = static_cast<double>(s.corridor.points.size());
  state.counters["pairs"] = static_cast<double>(pairs);
}
BENCHMARK(BM_EStep)->Arg(100)->Arg(500)->Unit(benchmark::kMillisecond);

// M-step, eqs. (19)-(29), over all surfaces: items = surfaces.
void BM_MStep(benchmark::State& state) {
  EStepSetup s(static_cast<int>(state.range(0)));
  s.run();
  const em::Neighbours neighbours = em::gridNeighbours(s.corridor.keys);
  for (auto _ : state) {
    std::vector<em::Surface> surfaces = s.corridor.surfaces;
    em::maximizeSurfaces(s.corridor.points, neighbours, s.resp, 1, surfaces);
    benchmark::DoNotOptimize(surfaces.data());
  }
  state.SetItemsProcessed(state.iterations() *
                          static_cast<std::int64_t>(s.corridor.surfaces.size()));
  state.counters["points"] = static_cast<double>(s.corridor.points.size());
}
BENCHMARK(BM_MStep)->Arg(100)->Arg(500)->Unit(benchmark::kMillisecond);

// The plane from moments alone (eqs. 24-27), per surface.
void BM_PlaneFromMoments(benchmark::State& state) {
  const Corridor c = makeCorridor(100);
  em::PlaneMoments m;
  m.reference = c.surfaces[0].rect.centre;
  for (const auto& p : c.points) {
    if (p.y() < -1.0)
      m.add(p, 1.0);
  }
  for (auto _ : state) {
    em::Rectangle rect = c.surfaces[0].rect;
    benchmark::DoNotOptimize(em::planeFromMoments(m, rect.normal, rect));
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_PlaneFromMoments);

// Eq. (29): the minimum-area rectangle around a surface's members (the right
// wall of the corridor: about 75 points per scan).
void BM_RectangleFit(benchmark::State& state) {
  const Corridor c = makeCorridor(static_cast<int>(state.range(0)));
  std::vector<std::int32_t> members;
  for (std::size_t i = 0; i < c.points.size(); ++i) {
    if (c.points[i].y() < -1.0)
      members.push_back(static_cast<std::int32_t>(i));
  }
  for (auto _ : state) {
    em::Rectangle rect = c.surfaces[0].rect;
    benchmark::DoNotOptimize(em::fitRectangle(c.points, members, rect));
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(members.size()));
  state.counters["members"] = static_cast<double>(members.size());
}
BENCHMARK(BM_RectangleFit)->Arg(20)->Arg(200)->Unit(benchmark::kMicrosecond);

// A model-selection round's coverage cut of one surface (coverage_cut.h:
// the grid's empty areas and the parts' refitted rectangles for every cut
// position along both axes), on the corridor's ceiling: items = members.
void BM_CoverageCut(benchmark::State& state) {
  const Corridor c = makeCorridor(static_cast<int>(state.range(0)));
  std::vector<std::int32_t> members;
  for (std::size_t i = 0; i < c.points.size(); ++i) {
    if (c.points[i].z() > 2.6 && std::abs(c.points[i].y()) < 1.05)
      members.push_back(static_cast<std::int32_t>(i));
  }
  em::Rectangle rect = c.surfaces[2].rect;
  em::fitRectangle(c.points, members, rect);
  const std::vector<double> loss(members.size(), 0.0);
  const em::PlanarEmOptions o;
  for (auto _ : state) {
    benchmark::DoNotOptimize(em::coverageCut(c.points, members, loss, rect, o.split_cell_m,
                                             o.empty_area_cost, o.kappa,
                                             static_cast<std::size_t>(o.min_support), true));
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(members.size()));
  state.counters["members"] = static_cast<double>(members.size());
}
BENCHMARK(BM_CoverageCut)->Arg(20)->Arg(200)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace pmap::bench

BENCHMARK_MAIN();
