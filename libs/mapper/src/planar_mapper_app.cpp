#include "pmap/mapper/planar_mapper_app.h"

#include <cmath>
#include <cstdio>
#include <memory>

#include "pmap/common/error.h"
#include "pmap/common/interrupt.h"
#include "pmap/common/text.h"
#include "pmap/input/label_inventory.h"
#include "pmap/mapper/map_products.h"
#include "pmap/mapper/output_guard.h"
#include "pmap/mapper/outputs.h"
#include "pmap/mapper/pipeline.h"
#include "pmap/mapper/staged_outputs.h"
#include "pmap/products/output_layout.h"

namespace pmap::mapper {
namespace {

// --list-labels: every label of the file, as rawlog-edit --info would.
void listLabels(const MapperArgs& args) {
  const input::LabelInventory inv = input::scanLabels(args.rawlog, 0);
  std::printf("%s: %zu records%s\n", args.rawlog.string().c_str(), inv.records,
              inv.error.empty() ? "" : " (then bad data)");
  std::printf("%-28s %-24s %10s %12s\n", "class", "label", "count", "first record");
  for (const input::LabelCount& c : inv.labels) {
    std::printf("%-28s %-24s %10zu %12zu\n", c.class_name.c_str(),
                c.label.empty() ? "'' (unlabelled)" : c.label.c_str(), c.count, c.first_record);
  }
  if (inv.odometry_actions > 0) {
    std::printf("%-28s %-24s %10zu\n", "CActionRobotMovement2D", "(actions: odometry)",
                inv.odometry_actions);
  }
  if (!inv.error.empty()) {
    throw InputError(inv.error);
  }
}

double pathLength(const poses::Trajectory& t) {
  double length = 0;
  for (std::size_t i = 1; i < t.size(); ++i) {
    const auto& a = t.poses()[i - 1].pose;
    const auto& b = t.poses()[i].pose;
    length += std::hypot(b.x - a.x, b.y - a.y, b.z - a.z);
  }
  return length;
}

void printSummary(const MapperArgs& args, const MappingResult& result) {
  if (args.poses_only) {
    const poses::Trajectory& trajectory = result.poses.trajectory;
    const auto& last = trajectory.poses().back().pose;
    std::fprintf(stderr,
                 "planar-mapper: %zu poses (%s), path %.2f m, final pose x %.4f m, y %.4f m, "
                 "yaw %.2f deg -> %s\n",
                 trajectory.size(), toString(result.poses.source), pathLength(trajectory), last.x,
                 last.y, last.yaw * 180.0 / M_PI, args.out.c_str());
    if (const auto& loops = result.poses.loops) {
      std::fprintf(stderr,
                   "planar-mapper: loop closure: %zu keyframes, %zu candidates, %zu loops "
                   "accepted\n",
                   loops->keyframes, loops->candidates, loops->accepted);
    }
    return;
  }
  const PointsResult& points = result.points;
  std::fprintf(stderr, "planar-mapper: %zu scans, %zu points, %zu raw triangles -> %s\n",
               points.placement.placed, points.map.size(), points.raw_triangles.size(),
               args.out.c_str());
  if (result.planar) {
    std::fprintf(stderr, "planar-mapper: EM %s; explained %.1f %%, %zu fine triangles\n",
                 result.planar->message.c_str(), 100.0 * result.planar->map.explained_fraction,
                 result.planar->map.fine_triangles.size());
  }
}

struct RunOutcome {
  MappingResult result;
  std::optional<MapProducts> products;
};

/// Maps and writes every output into a staging folder beside --out, swapped
/// in as a whole at the end with the run's manifest (staged_outputs.h).
/// SIGINT / SIGTERM / SIGHUP throw Interrupted: the staging folder is
/// removed, --out stays as it was.
RunOutcome mapAndWrite(const MapperConfig& config, const MapperArgs& args,
                       const std::vector<std::string>& command, StageClock& clock, LiveView* live) {
  InterruptGuard guard;
  StagedOutputs staged(args.out);
  MapperArgs staged_args = args;
  staged_args.out = staged.dir();  // everything is written there, snapshots included
  if (args.snapshot_every > 0 && !args.quiet) {
    std::fprintf(stderr, "planar-mapper: snapshots go to %s until the run ends\n",
                 (staged.dir() / products::OutputLayout::kSnapshotsDir).c_str());
  }
  RunOutcome outcome;
  MappingResult& result = outcome.result;
  result = runPipeline(config, staged_args, clock, live);
  result.warnings.insert(result.warnings.begin(), staged.warnings().begin(),
                         staged.warnings().end());
  result.warnings.insert(result.warnings.begin(), config.warnings.begin(), config.warnings.end());
  throwIfInterrupted();
  if (result.planar) {
    auto in_texture = clock.enter(Stage::kTexture);
    outcome.products = buildMapProducts(config, args, result);
  }
  throwIfInterrupted();
  const MapProducts* products = outcome.products ? &*outcome.products : nullptr;
  writeOutputs(config, args, result, products, clock, staged.dir());
  throwIfInterrupted();  // the last chance: from here on the run completes
  for (std::string& note : staged.commit(manifestHeader(config, command))) {
    result.warnings.push_back(std::move(note));
  }
  return outcome;
}

}  // namespace

bool PlanarMapperApp::initialize(int argc, const char* const* argv) {
  command_.assign(argv, argv + argc);
  args_ = parseMapperArgs(argc, argv);
  if (!args_) {
    return false;
  }
  config_ = loadMapperConfig(args_->config);
  if (args_->list_labels) {
    return true;
  }
  if (args_->rawlog_is_sample && !args_->quiet) {
    std::fprintf(stderr,
                 "planar-mapper: no --rawlog given: mapping the bundled sample %s with %s\n",
                 args_->rawlog.c_str(), args_->config.c_str());
  }
  checkOutputsSpareInputs(*args_);  // before any work: never write over an input
  return true;
}

void PlanarMapperApp::run() {
  if (args_->list_labels) {
    listLabels(*args_);
    return;
  }
  StageClock clock;
  std::unique_ptr<LiveView> live;
  if (args_->gui) {
    LiveViewOptions options;
    options.hold_s = args_->gui_hold_s;
    live = std::make_unique<LiveView>(options);
  }
  RunOutcome outcome = mapAndWrite(*config_, *args_, command_, clock, live.get());
  const MappingResult& result = outcome.result;
  const std::optional<MapProducts>& products = outcome.products;
  if (live) {
    live->finish(products ? products->model : products::MapModel{}, result.points.map);
  }
  for (const std::string& w : result.warnings) {  // also with --quiet
    std::fprintf(stderr, "planar-mapper: warning: %s\n", w.c_str());
  }
  if (!args_->quiet) {
    printSummary(*args_, result);
    if (!result.input.truncation.empty()) {
      std::fprintf(stderr, "planar-mapper: warning: %s (accepted)\n",
                   result.input.truncation.c_str());
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
  } catch (const Interrupted& e) {
    std::fprintf(stderr,
                 "planar-mapper: %s: stopped; the previous outputs are unchanged, the staging "
                 "folder removed\n",
                 e.what());
    return reraiseWithDefaultAction(e.signalNumber());
  } catch (const Error& e) {
    for (const std::string& line : splitLines(e.what())) {
      std::fprintf(stderr, "planar-mapper: error: %s\n", line.c_str());
    }
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
