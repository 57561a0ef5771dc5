#include "pmap/mapper/planar_mapper_app.h"

#include <chrono>
#include <cstdio>
#include <memory>

#include "pmap/common/error.h"
#include "pmap/common/text.h"
#include "pmap/mapper/map_products.h"
#include "pmap/mapper/output_guard.h"
#include "pmap/mapper/outputs.h"
#include "pmap/mapper/pipeline.h"

namespace pmap::mapper {

bool PlanarMapperApp::initialize(int argc, const char* const* argv) {
  args_ = parseMapperArgs(argc, argv);
  if (!args_) {
    return false;
  }
  config_ = loadMapperConfig(args_->config);
  checkOutputsSpareInputs(*args_);  // before any work: never write over an input
  return true;
}

void PlanarMapperApp::run() {
  const auto t0 = std::chrono::steady_clock::now();
  std::unique_ptr<LiveView> live;
  if (args_->gui) {
    LiveViewOptions options;
    options.hold_s = args_->gui_hold_s;
    live = std::make_unique<LiveView>(options);
  }
  const MappingResult result = runPipeline(*config_, *args_, live.get());
  std::optional<MapProducts> products;
  if (result.em) {
    products = buildMapProducts(*config_, *args_, result);
  }
  // Everything before writing, the map products (textures) included.
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  writeOutputs(*config_, *args_, result, products ? &*products : nullptr, elapsed);
  if (live) {
    live->finish(products ? products->model : products::MapModel{}, result.map);
  }

  for (const std::string& w : result.warnings) {  // also with --quiet
    std::fprintf(stderr, "planar-mapper: warning: %s\n", w.c_str());
  }
  if (!args_->quiet) {
    std::fprintf(stderr, "planar-mapper: %zu scans, %zu points, %zu raw triangles -> %s\n",
                 result.placement.placed, result.map.size(), result.raw_triangles.size(),
                 args_->out.c_str());
    if (result.em) {
      std::fprintf(stderr, "planar-mapper: EM %s; explained %.1f %%, %zu fine triangles\n",
                   result.em->message.c_str(), 100.0 * result.em->map.explained_fraction,
                   result.em->map.fine_triangles.size());
    }
    if (!result.truncation.empty()) {
      std::fprintf(stderr, "planar-mapper: warning: %s (accepted)\n", result.truncation.c_str());
    }
  }
}

int planarMapperMain(int argc, const char* const* argv) {
  try {
    PlanarMapperApp app;
    if (!app.initialize(argc, argv)) {
      return 0;
    }
    app.run();
    return 0;
  } catch (const Error& e) {
    std::fprintf(stderr, "planar-mapper: error: %s\n", e.what());
    return e.exitCode();
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "planar-mapper: error: out of memory\n");
    return static_cast<int>(ExitCode::kProcessing);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "planar-mapper: error: internal failure: %s\n",
                 oneLineError(e.what()).c_str());
    return static_cast<int>(ExitCode::kProcessing);
  }
}

}  // namespace pmap::mapper
