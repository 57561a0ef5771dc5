// The files of a run, derived from the --out PREFIX: PREFIX.rawlog,
// PREFIX_Images/ (MRPT's "<rawlog name without extension>_Images" convention,
// where RawLogViewer and CImage::setImagesPathBase users look for external
// images), PREFIX.gt.json and PREFIX.poses.txt. The simulator writes them
// under temporary names and replaces the four together (pmap::OutputSet).
#pragma once

#include <filesystem>
#include <string>

#include "pmap/common/output_set.h"

namespace pmap::sim {

struct OutputPaths {
  std::filesystem::path rawlog;
  std::filesystem::path images_dir;
  std::filesystem::path gt_json;
  std::filesystem::path poses_txt;
  std::string images_dir_name;  ///< images_dir relative to the gt.json's directory

  /// A trailing ".rawlog" on `prefix` is ignored. Throws ConfigError if empty.
  static OutputPaths fromPrefix(const std::string& prefix);

  /// Registers the four outputs in `set` (in commit order: images, gt.json,
  /// poses.txt, rawlog) and returns their temporary paths; images_dir_name
  /// stays the final name, which the rawlog and gt.json refer to. Throws
  /// OutputError (an unwritable directory, a target of the wrong kind).
  OutputPaths stageIn(OutputSet& set) const;
};

}  // namespace pmap::sim
