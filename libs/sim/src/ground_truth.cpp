#include "pmap/sim/ground_truth.h"

#include <cassert>
#include <cstdio>

#include "pmap/common/atomic_file.h"

namespace pmap::sim {

void GroundTruthRecorder::addPose(double t_s, const Pose2D& pose) {
  if (!poses_.empty() && poses_.back().t_s == t_s) {
    return;
  }
  assert(poses_.empty() || poses_.back().t_s < t_s);
  poses_.push_back(TimedPose{t_s, pose});
}

void GroundTruthRecorder::addStructureScan(double t_s, const std::string& label,
                                           const std::vector<int>& hits) {
  scans_.push_back(StructureScan{t_s, label, hits});
}

void GroundTruthRecorder::addImage(const ImageRecord& record) {
  images_.push_back(record);
}

OrderedJson GroundTruthRecorder::toJson(const World& world, const GroundTruthMeta& meta) const {
  OrderedJson doc;
  doc["format"] = "pmap-gt/1";
  doc["world"] = meta.world_name;
  doc["world_file"] = meta.world_file;
  if (!meta.octomap.is_null()) {
    doc["octomap"] = meta.octomap;
  }
  doc["seed"] = meta.seed;
  doc["sigma_m"] = meta.sigma_m;
  doc["rawlog_format"] = meta.rawlog_format;
  doc["frame"] = "world frame; metres; z up; angles in radians; timestamps in UNIX seconds";
  doc["start_time"] = meta.start_time_s;
  doc["duration_s"] = meta.duration_s;
  doc["path_length_m"] = meta.path_length_m;
  doc["counts"] = {{"cycles", meta.cycles},
                   {"poses", poses_.size()},
                   {"structure_scans", scans_.size()},
                   {"images", meta.images},
                   {"surfaces", world.surfaces.size()},
                   {"posters", world.posters.size()},
                   {"clutter", world.clutter.size()}};
  doc["sensors"] = sensorsJson(world, meta.intrinsics, meta.cameras_enabled, meta.odometry);
  doc["config"] = configJson(world);
  doc["pose_fields"] = {"t", "x", "y", "z", "yaw", "pitch", "roll"};
  OrderedJson poses = OrderedJson::array();
  for (const TimedPose& p : poses_) {
    poses.push_back({p.t_s, p.pose.x, p.pose.y, 0.0, p.pose.yaw, 0.0, 0.0});
  }
  doc["poses"] = poses;
  doc["surfaces"] = surfacesJson(world);
  doc["posters"] = postersJson(world, meta.images_dir_name);
  doc["clutter"] = clutterJson(world);
  if (!world.people.empty()) {  // only then: the files of worlds without people stay as they were
    doc["people"] = peopleJson(world);
  }
  OrderedJson scans = OrderedJson::array();
  for (std::size_t i = 0; i < scans_.size(); ++i) {
    scans.push_back({{"index", i},
                     {"timestamp", scans_[i].t_s},
                     {"label", scans_[i].label},
                     {"hits", scans_[i].hits}});
  }
  doc["structure_scans"] = scans;
  OrderedJson images = OrderedJson::array();
  for (const ImageRecord& image : images_) {
    images.push_back(imageJson(image, meta.images_dir_name));
  }
  doc["images"] = images;
  return doc;
}

std::string GroundTruthRecorder::posesText() const {
  std::string out = "# timestamp x y z yaw pitch roll (true robot poses; s, m, rad)\n";
  char line[256];
  for (const TimedPose& p : poses_) {
    std::snprintf(line, sizeof(line), "%.6f %.6f %.6f %.6f %.9f %.9f %.9f\n", p.t_s, p.pose.x,
                  p.pose.y, 0.0, p.pose.yaw, 0.0, 0.0);
    out += line;
  }
  return out;
}

void GroundTruthRecorder::write(const std::filesystem::path& gt_json,
                                const std::filesystem::path& poses_txt, const World& world,
                                const GroundTruthMeta& meta) const {
  writeTextFileAtomically(gt_json, formatGroundTruth(toJson(world, meta)));
  writeTextFileAtomically(poses_txt, posesText());
}

}  // namespace pmap::sim
