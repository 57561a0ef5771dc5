#include "pmap/sim/output_paths.h"

#include "pmap/common/error.h"

namespace pmap::sim {
namespace fs = std::filesystem;

OutputPaths OutputPaths::fromPrefix(const std::string& prefix_in) {
  std::string prefix = prefix_in;
  const std::string ext = ".rawlog";
  if (prefix.size() > ext.size() &&
      prefix.compare(prefix.size() - ext.size(), ext.size(), ext) == 0) {
    prefix.resize(prefix.size() - ext.size());
  }
  if (prefix.empty() || prefix.back() == '/' || fs::path(prefix).filename().empty()) {
    throw ConfigError("--out: \"" + prefix_in + "\" is not a file prefix (e.g. out/run1)");
  }
  OutputPaths p;
  p.rawlog = prefix + ".rawlog";
  p.images_dir = prefix + "_Images";
  p.gt_json = prefix + ".gt.json";
  p.poses_txt = prefix + ".poses.txt";
  p.images_dir_name = p.images_dir.filename().string();
  return p;
}

OutputPaths OutputPaths::stageIn(OutputSet& set) const {
  OutputPaths staged = *this;
  staged.images_dir = set.add(images_dir, OutputSet::Kind::kDirectory);
  staged.gt_json = set.add(gt_json, OutputSet::Kind::kFile);
  staged.poses_txt = set.add(poses_txt, OutputSet::Kind::kFile);
  staged.rawlog = set.add(rawlog, OutputSet::Kind::kFile);
  return staged;
}

}  // namespace pmap::sim
