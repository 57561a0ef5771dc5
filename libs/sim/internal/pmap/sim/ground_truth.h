// Collects the ground truth of a run (true poses at every observation
// timestamp, the id hit by every true structure-laser ray, the imperfections
// and sharpness of every camera image) and writes
// PREFIX.gt.json ("pmap-gt/1", doc/ground-truth.md) and PREFIX.poses.txt
// (the mapper's poses.txt format: "timestamp x y z yaw pitch roll").
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "pmap/sim/frame_imaging.h"
#include "pmap/sim/ground_truth_json.h"
#include "pmap/sim/pose.h"

namespace pmap::sim {

struct GroundTruthMeta {
  std::string world_name;
  std::string world_file;
  OrderedJson octomap;  ///< voxel worlds: the tree read (octomapJson), null otherwise
  std::uint64_t seed = 0;
  double sigma_m = 0.0;
  std::string rawlog_format;
  double start_time_s = 0.0;
  std::string images_dir_name;  ///< relative to the gt.json's directory
  bool cameras_enabled = true;
  PinholeIntrinsics intrinsics;
  OdometryTruth odometry;
  double path_length_m = 0.0;
  double duration_s = 0.0;
  std::size_t cycles = 0;
  std::size_t images = 0;
};

class GroundTruthRecorder {
 public:
  /// Poses must come in non-decreasing time; a repeated timestamp is kept once.
  void addPose(double t_s, const Pose2D& pose);
  /// One entry per structure (vertical laser) observation, in file order
  /// (`hits` empty where objects have no ids: voxel worlds).
  void addStructureScan(double t_s, const std::string& label, const std::vector<int>& hits);
  /// One entry per camera image, in file order.
  void addImage(const ImageRecord& record);

  std::size_t poseCount() const { return poses_.size(); }
  std::size_t structureScanCount() const { return scans_.size(); }
  std::size_t imageCount() const { return images_.size(); }

  OrderedJson toJson(const World& world, const GroundTruthMeta& meta) const;
  /// The poses.txt text: a '#' header line, then one pose per line.
  std::string posesText() const;

  /// Both files, each written atomically.
  void write(const std::filesystem::path& gt_json, const std::filesystem::path& poses_txt,
             const World& world, const GroundTruthMeta& meta) const;

 private:
  struct TimedPose {
    double t_s;
    Pose2D pose;
  };
  struct StructureScan {
    double t_s;
    std::string label;
    std::vector<int> hits;
  };
  std::vector<TimedPose> poses_;
  std::vector<StructureScan> scans_;
  std::vector<ImageRecord> images_;
};

}  // namespace pmap::sim
