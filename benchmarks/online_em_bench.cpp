// Micro-benchmark of the online EM's update per scan (paper section V) on a
// synthetic corridor of 600 scans (48 m, the size of the default world):
// each iteration adds the next scan; the mean is over the whole run.
#include <benchmark/benchmark.h>

#include <memory>

#include "pmap/em/online_em.h"
#include "synthetic_corridor.h"

namespace pmap::bench {
namespace {

constexpr int kScans = 600;

void BM_OnlineUpdatePerScan(benchmark::State& state) {
  static const Corridor corridor = makeCorridor(kScans);
  std::unique_ptr<em::OnlineEm> online;
  int scan = kScans;
  for (auto _ : state) {
    if (scan == kScans) {  // start a new run (not timed)
      state.PauseTiming();
      online = std::make_unique<em::OnlineEm>(em::PlanarEmOptions{}, em::OnlineEmOptions{});
      scan = 0;
      state.ResumeTiming();
    }
    const auto a = static_cast<std::ptrdiff_t>(corridor.scan_start[static_cast<std::size_t>(scan)]);
    const auto b =
        static_cast<std::ptrdiff_t>(corridor.scan_start[static_cast<std::size_t>(scan) + 1]);
    const std::vector<Eigen::Vector3d> points(corridor.points.begin() + a,
                                              corridor.points.begin() + b);
    const std::vector<em::GridKey> keys(corridor.keys.begin() + a, corridor.keys.begin() + b);
    benchmark::DoNotOptimize(online->addScan(points, keys));
    ++scan;
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["surfaces"] = online ? online->surfaceCount() : 0;
}
BENCHMARK(BM_OnlineUpdatePerScan)->Iterations(kScans)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace pmap::bench

BENCHMARK_MAIN();
