// The files of a run, derived from the --out PREFIX: PREFIX.rawlog,
// PREFIX_Images/ (MRPT's "<rawlog name without extension>_Images" convention,
// where RawLogViewer and CImage::setImagesPathBase users look for external
// images), PREFIX.gt.json and PREFIX.poses.txt. Images are written into a
// temporary directory that replaces PREFIX_Images/ only on commit.
#pragma once

#include <filesystem>
#include <string>

namespace pmap::sim {

struct OutputPaths {
  std::filesystem::path rawlog;
  std::filesystem::path images_dir;
  std::filesystem::path images_tmp_dir;
  std::filesystem::path gt_json;
  std::filesystem::path poses_txt;
  std::string images_dir_name;  ///< images_dir relative to the gt.json's directory

  /// A trailing ".rawlog" on `prefix` is ignored. Throws ConfigError if empty.
  static OutputPaths fromPrefix(const std::string& prefix);
};

/// Creates the output directory and an empty temporary images directory;
/// removes the temporary directory on destruction unless committed.
class ImagesDirTransaction {
 public:
  explicit ImagesDirTransaction(const OutputPaths& paths);  ///< throws OutputError
  ~ImagesDirTransaction();
  ImagesDirTransaction(const ImagesDirTransaction&) = delete;
  ImagesDirTransaction& operator=(const ImagesDirTransaction&) = delete;

  /// Replaces images_dir by the temporary directory. Throws OutputError.
  void commit();

 private:
  const OutputPaths& paths_;
  bool committed_ = false;
};

}  // namespace pmap::sim
