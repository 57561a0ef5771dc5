// planar-mapper never writes over its own input: checked before any work, so
// a bad --out costs nothing and leaves every file as it was.
#pragma once

#include <string>
#include <vector>

#include "pmap/mapper/mapper_args.h"

namespace pmap::mapper {

/// Names planar-mapper may write directly into its output directory, and
/// the subdirectories it writes into (doc/outputs.md).
const std::vector<std::string>& outputFileNames();
const std::vector<std::string>& outputSubdirectories();

/// Throws OutputError (exit 4) when writing the outputs of `args` could
/// replace an input file (rawlog, cloud, poses, ini): --out is that file, or
/// the file lies in the output directory under a name planar-mapper writes
/// or inside one of its subdirectories. Symbolic links are resolved.
void checkOutputsSpareInputs(const MapperArgs& args);

}  // namespace pmap::mapper
