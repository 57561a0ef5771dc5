#include "pmap/mapper/map_products.h"

#include <mrpt/poses/CPose3D.h>

#include <chrono>

#include "pmap/common/progress.h"

namespace pmap::mapper {
namespace {

std::vector<Eigen::Vector3d> pathOf(const poses::Trajectory& trajectory) {
  std::vector<Eigen::Vector3d> path;
  for (const poses::TimedPose& p : trajectory.poses()) {
    path.emplace_back(p.pose.x, p.pose.y, p.pose.z);
  }
  return path;
}

// Camera frames placed with the pose interpolated at each image's time.
std::vector<texture::CameraFrame> placeFrames(const MapperConfig& config,
                                              const MappingResult& result,
                                              std::size_t& without_pose) {
  std::vector<texture::CameraFrame> frames;
  for (const auto& obs : result.input.images) {
    const auto pose = result.poses.trajectory.at(mrpt::Clock::toDouble(obs->timestamp),
                                                 config.sensors.max_pose_gap_s);
    if (!pose) {
      ++without_pose;
      continue;
    }
    frames.push_back(texture::makeFrame(obs, mrpt::poses::CPose3D(*pose)));
  }
  return frames;
}

}  // namespace

MapProducts buildMapProducts(const MapperConfig& config, const MapperArgs& args,
                             const MappingResult& result) {
  const auto t0 = std::chrono::steady_clock::now();
  MapProducts p;
  p.model = products::buildMapModel(result.planar->map, result.points.map.xyz(),
                                    pathOf(result.poses.trajectory));
  if (args.no_textures) {
    p.untextured_reason = "--no-textures";
  } else if (!config.texture.enabled) {
    p.untextured_reason = "[Texture] enabled = false";
  } else if (result.input.images.empty()) {
    p.untextured_reason = "no camera images (labels in [Sensors] cameras)";
  } else {
    p.frames = placeFrames(config, result, p.frames_without_pose);
    const std::filesystem::path images_dir = texture::externalImagesDir(args.rawlog);
    ProgressLine progress("planar-mapper: textures", ProgressOptions{!args.quiet, 1.0, true});
    std::uint64_t reads = 0;
    const std::string of = ", " + std::to_string(p.frames.size()) + " frames";
    p.texture = texture::textureMap(
        p.model, p.frames,
        [&](const texture::CameraFrame& f) {
          progress.update(++reads, 0, "image reads (about 3 per used frame" + of + ")");
          return texture::loadFrameImage(f, images_dir);
        },
        config.texture);
    progress.finish(p.texture->message);
  }
  p.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return p;
}

}  // namespace pmap::mapper
