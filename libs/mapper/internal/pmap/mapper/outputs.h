// Files planar-mapper writes into its output directory (doc/outputs.md).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "pmap/mapper/map_products.h"
#include "pmap/mapper/mapper_args.h"
#include "pmap/mapper/mapper_config.h"
#include "pmap/mapper/pipeline.h"
#include "pmap/products/output_manifest.h"

namespace pmap::mapper {

/// Writes poses.txt, poses.tum, scans.csv, points.ply, raw.wrl, raw.glb,
/// online.csv, surfaces.csv, the map files (map_outputs.h), summary.json and
/// effective.ini into `dir`, the run's staging folder (staged_outputs.h):
/// only the poses, summary.json and effective.ini with --poses-only. The
/// names are products::OutputLayout's. summary.json's timing_s is read off
/// `clock` (the writing included, as stage "write"). Polls
/// pmap::throwIfInterrupted() between files. Throws OutputError.
void writeOutputs(const MapperConfig& config, const MapperArgs& args, const MappingResult& result,
                  const MapProducts* products, StageClock& clock, const std::filesystem::path& dir);

/// manifest.json's header for this run (doc/outputs.md): the program and its
/// version, `command` (argv), the SHA-256 of the effective configuration
/// (effective.ini without its comment header) and the time.
products::OutputManifest manifestHeader(const MapperConfig& config,
                                        const std::vector<std::string>& command);

}  // namespace pmap::mapper
