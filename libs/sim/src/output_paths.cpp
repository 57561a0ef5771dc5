#include "pmap/sim/output_paths.h"

#include <unistd.h>

#include "pmap/common/atomic_file.h"
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
  p.images_tmp_dir = prefix + "_Images.tmp-" + std::to_string(::getpid());
  p.gt_json = prefix + ".gt.json";
  p.poses_txt = prefix + ".poses.txt";
  p.images_dir_name = p.images_dir.filename().string();
  return p;
}

ImagesDirTransaction::ImagesDirTransaction(const OutputPaths& paths) : paths_(paths) {
  const fs::path parent = paths.rawlog.parent_path();
  ensureWritableDirectory(parent.empty() ? fs::path(".") : parent);
  std::error_code ec;
  fs::remove_all(paths.images_tmp_dir, ec);
  ensureWritableDirectory(paths.images_tmp_dir);
  if (fs::exists(paths.images_dir, ec) && !fs::is_directory(paths.images_dir, ec)) {
    throw OutputError(paths.images_dir.string() + ": exists and is not a directory");
  }
}

ImagesDirTransaction::~ImagesDirTransaction() {
  if (!committed_) {
    std::error_code ec;
    fs::remove_all(paths_.images_tmp_dir, ec);
  }
}

void ImagesDirTransaction::commit() {
  std::error_code ec;
  const fs::path old = paths_.images_dir.string() + ".old-" + std::to_string(::getpid());
  const bool had_old = fs::exists(paths_.images_dir, ec);
  if (had_old) {
    fs::rename(paths_.images_dir, old, ec);
    if (ec) {
      throw OutputError(paths_.images_dir.string() + ": cannot replace: " + ec.message());
    }
  }
  fs::rename(paths_.images_tmp_dir, paths_.images_dir, ec);
  if (ec) {
    std::error_code ignored;
    if (had_old) {
      fs::rename(old, paths_.images_dir, ignored);
    }
    throw OutputError(paths_.images_dir.string() +
                      ": cannot move images into place: " + ec.message());
  }
  committed_ = true;
  if (had_old) {
    fs::remove_all(old, ec);
  }
}

}  // namespace pmap::sim
