// Files planar-mapper writes into its output directory (doc/outputs.md).
#pragma once

#include <filesystem>

#include "pmap/mapper/map_products.h"
#include "pmap/mapper/mapper_args.h"
#include "pmap/mapper/mapper_config.h"

#include "pmap/mapper/pipeline.h"

namespace pmap::mapper {

/// Writes poses.txt, scans.csv, points.ply, raw.wrl, summary.json and
/// effective.ini (only poses.txt, summary.json and effective.ini with
/// --poses-only). `total_s` is the wall time so far; writing time is added.
void writeOutputs(const MapperConfig& config, const MapperArgs& args, const MappingResult& result,
                  const MapProducts* products, double elapsed_before_write_s);

}  // namespace pmap::mapper
