// planar-mapper never writes over its own input, and never deletes or moves a
// file it did not write (doc/outputs.md): checked before any work, so a bad
// --out costs nothing and leaves every file as it was. The names are those of
// products::OutputLayout.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "pmap/mapper/mapper_args.h"

namespace pmap::mapper {

/// Throws OutputError (exit 4) when writing the outputs of `args` could
/// replace an input file (rawlog, cloud, poses, ini): --out is that file, the
/// file lies in the output folder under a name OutputLayout names or inside
/// one of its folders (report/, textures/, snapshots/), or it is the lock
/// file beside the output folder. Symbolic links are resolved.
void checkOutputsSpareInputs(const MapperArgs& args);

/// Entries of the existing folder `out` that OutputLayout does not name
/// (relative paths, sorted; a folder the layout does not name is one entry).
std::vector<std::string> foreignEntries(const std::filesystem::path& out);

/// Throws OutputError (exit 4) unless the run may replace the folder `out`
/// (absolute, links resolved) as a whole: it does not exist, or it is a
/// writable directory that is no mount point and either has a manifest.json
/// (an output folder: foreign entries are kept in place) or holds nothing
/// but files OutputLayout names. `shown` is --out as given, for messages.
void checkOutputFolder(const std::filesystem::path& out, const std::string& shown);

}  // namespace pmap::mapper
