// The streaming part of the pipeline on a rawlog: records -> input steps ->
// poses -> placed structure points -> raw mesh and the online EM.
#pragma once

#include "pmap/common/stage_clock.h"
#include "pmap/mapper/live_view.h"
#include "pmap/mapper/mapper_args.h"
#include "pmap/mapper/mapper_config.h"
#include "pmap/mapper/mapping_result.h"

namespace pmap::mapper {

/// Reads the rawlog of `args` into `result` (input, poses, points; the
/// planar map too in the online mode), timing its stages on `clock`.
/// Throws ConfigError (labels), InputError (bad data, nothing to map).
void runRawlog(const MapperConfig& config, const MapperArgs& args, StageClock& clock,
               LiveView* live, MappingResult& result);

}  // namespace pmap::mapper
