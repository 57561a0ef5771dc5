// Files planar-mapper writes into its output directory (doc/outputs.md).
#pragma once

#include <filesystem>

#include "pmap/mapper/map_products.h"
#include "pmap/mapper/mapper_args.h"
#include "pmap/mapper/mapper_config.h"

#include "pmap/mapper/pipeline.h"

namespace pmap::mapper {

/// Writes poses.txt, poses.tum, scans.csv, points.ply, raw.wrl, summary.json
/// and effective.ini (only the poses, summary.json and effective.ini with
/// --poses-only). summary.json's timing_s is read off `clock` (the writing
/// included, as stage "write").
void writeOutputs(const MapperConfig& config, const MapperArgs& args, const MappingResult& result,
                  const MapProducts* products, StageClock& clock);

}  // namespace pmap::mapper
