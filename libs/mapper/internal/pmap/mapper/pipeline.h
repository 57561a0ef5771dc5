// The mapping pipeline as data flows: rawlog (or a PLY cloud) -> input
// steps -> poses -> placed structure points -> raw mesh -> the EM planar map
// (online, scan by scan, or offline at the end) -> the refinement.
// Streaming: memory grows with the map, not with the file.
#pragma once

#include "pmap/common/stage_clock.h"
#include "pmap/mapper/live_view.h"
#include "pmap/mapper/mapper_args.h"
#include "pmap/mapper/mapper_config.h"
#include "pmap/mapper/mapping_result.h"

namespace pmap::mapper {

/// Runs the pipeline on a rawlog or a PLY cloud, timing its stages on
/// `clock` and showing progress in `live` (--gui) when given. Throws
/// ConfigError, InputError (bad data, nothing to map), ProcessingError.
MappingResult runPipeline(const MapperConfig& config, const MapperArgs& args, StageClock& clock,
                          LiveView* live = nullptr);

/// "Nothing found" (doc/robustness.md): a run that read its input correctly
/// but kept no structure point, or found no planar surface, is not an error.
/// It exits 0 with valid, empty outputs; this adds the warning that says so.
void noteNothingFound(const MapperArgs& args, MappingResult& result);
/// Adds a warning when the offline EM stopped at max_iterations.
void noteUnconverged(const MapperConfig& config, MappingResult& result);

}  // namespace pmap::mapper
