// indoor-sim's engine: loads and expands a world (or, for a voxel world, reads
// its OctoMap tree), drives the robot along its path and writes the rawlog,
// the external images, the ground truth and the true poses (doc/simulator.md,
// doc/ground-truth.md). Same world + seed + options give byte-identical outputs.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "pmap/sim/output_paths.h"
#include "pmap/sim/rawlog_writer.h"
#include "pmap/sim/ray_caster.h"
#include "pmap/sim/trajectory.h"
#include "pmap/sim/voxel_ray_caster.h"
#include "pmap/sim/voxel_world.h"
#include "pmap/sim/world.h"

namespace pmap::sim {

struct SimulatorOptions {
  std::filesystem::path world_file;  ///< a world JSON file
  std::uint64_t seed = 1;            ///< every random draw derives from it
  std::optional<double> sigma_m;     ///< overrides noise.range_sigma_m, metres
  RawlogFormat format = RawlogFormat::kObservations;
  std::optional<double> duration_s;  ///< cut the run after this many seconds
  bool cameras = true;               ///< false: no images even if the world enables them
  std::string out_prefix;            ///< PREFIX of the outputs
  bool progress = true;              ///< progress line on stderr
  bool validate(std::string* why) const;
};

struct SimulationSummary {
  OutputPaths paths;
  std::size_t cycles = 0;
  std::size_t structure_scans = 0;
  std::size_t images = 0;
  std::size_t rawlog_objects = 0;
  std::size_t surfaces = 0;
  std::uint64_t occupied_voxels = 0;  ///< voxel worlds: the tree's occupied voxels
  double duration_s = 0.0;            ///< simulated time, seconds
  double path_length_m = 0.0;         ///< full path length (even if cut)
};

class Simulator {
 public:
  /// Loads and expands the world and checks the path (ConfigError); a voxel
  /// world's tree that cannot be used is an InputError.
  explicit Simulator(SimulatorOptions options);
  ~Simulator();

  /// Writes the four outputs under temporary names, then replaces the old set
  /// with them all or nothing (pmap::OutputSet). Polls pmap::throwIfInterrupted()
  /// before each cycle and before the commit. On any exception (ConfigError,
  /// OutputError, Interrupted) the previous outputs are untouched and no
  /// temporary remains.
  SimulationSummary run();

  const World& world() const { return world_; }
  const Trajectory& trajectory() const { return *trajectory_; }
  /// The occupied voxels of a voxel world, nullptr for a world of rectangles.
  const VoxelWorld* voxels() const { return voxels_.get(); }
  const SimulatorOptions& options() const { return options_; }
  /// Number of cycles run() will simulate.
  std::size_t cycleCount() const;

 private:
  SimulatorOptions options_;
  World world_;
  std::unique_ptr<Trajectory> trajectory_;
  std::unique_ptr<RayCaster> caster_;             ///< worlds of rectangles and solids
  std::unique_ptr<VoxelWorld> voxels_;            ///< voxel worlds
  std::unique_ptr<VoxelRayCaster> voxel_caster_;  ///< voxel worlds
};

}  // namespace pmap::sim
