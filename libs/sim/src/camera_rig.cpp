#include "pmap/sim/camera_rig.h"

#include <cstdio>
#include <future>
#include <opencv2/imgcodecs.hpp>

#include "pmap/common/atomic_file.h"
#include "pmap/common/error.h"
#include "pmap/sim/observation_factory.h"
#include "pmap/sim/poster_art.h"
#include "pmap/sim/rng.h"

namespace pmap::sim {
namespace {

void writeEncoded(const std::filesystem::path& path, const cv::Mat& image, const std::string& ext,
                  const std::vector<int>& params) {
  std::vector<unsigned char> bytes;
  if (!cv::imencode(ext, image, bytes, params)) {
    throw OutputError(path.string() + ": cannot encode image");
  }
  writeFileAtomically(
      path,
      [&](std::ostream& out) {
        out.write(reinterpret_cast<const char*>(bytes.data()),
                  static_cast<std::streamsize>(bytes.size()));
      },
      true);
}

RigidTransform cameraToWorld(const CameraMount& mount, const Pose2D& robot) {
  return compose(toTransform(robot), toTransform(cameraMountPose(mount)));
}

}  // namespace

std::string cameraImageFileName(const std::string& label, int index) {
  char name[32];
  std::snprintf(name, sizeof(name), "_%06d.jpg", index);
  return label + name;
}

std::vector<cv::Mat> writePosterImages(const World& world, std::uint64_t seed,
                                       const std::filesystem::path& dir) {
  std::vector<cv::Mat> images;
  for (const Poster& p : world.posters) {
    images.push_back(generatePosterImage(
        p.width_px, p.height_px, deriveSeed(seed, "poster", static_cast<std::uint64_t>(p.id))));
    writeEncoded(dir / ("poster_" + std::to_string(p.id) + ".png"), images.back(), ".png",
                 {cv::IMWRITE_PNG_COMPRESSION, 6});
  }
  return images;
}

void writeJpeg(const std::filesystem::path& path, const cv::Mat& image, int quality) {
  writeEncoded(path, image, ".jpg", {cv::IMWRITE_JPEG_QUALITY, quality});
}

CameraRig::CameraRig(const World& world, const std::vector<cv::Mat>& posters, std::uint64_t seed,
                     std::filesystem::path images_dir)
    : world_(world),
      seed_(seed),
      images_dir_(std::move(images_dir)),
      pipeline_(world.sensors.cameras),
      renderer_(world, posters, static_cast<std::uint32_t>(deriveSeed(seed, "textures"))) {}

cv::Mat CameraRig::renderMount(const CameraMount& mount, const Pose2D& robot) const {
  return pipeline_.opticalImage(
      renderer_.render(pipeline_.renderIntrinsics(), cameraToWorld(mount, robot)));
}

FrameEffects CameraRig::frameEffects(const std::string& label, int index) const {
  return drawFrameEffects(world_.sensors.cameras, deriveSeed(seed_, "image-effects:" + label,
                                                             static_cast<std::uint64_t>(index)));
}

DevelopedFrame CameraRig::developMount(const CameraMount& mount, const Pose2D& robot,
                                       int index) const {
  const cv::Mat render =
      renderer_.render(pipeline_.renderIntrinsics(), cameraToWorld(mount, robot));
  const std::uint64_t noise_seed =
      deriveSeed(seed_, "image-noise:" + mount.label, static_cast<std::uint64_t>(index));
  return pipeline_.develop(render, frameEffects(mount.label, index), noise_seed);
}

Capture CameraRig::capture(const Pose2D& robot, int index, mrpt::Clock::time_point stamp) const {
  const CameraOptions& opts = world_.sensors.cameras;
  Capture out;
  out.records.resize(opts.mounts.size());
  // Each image depends only on (seed, label, index): rendering in parallel is deterministic.
  std::vector<std::future<void>> jobs;
  for (std::size_t i = 0; i < opts.mounts.size(); ++i) {
    jobs.push_back(std::async(std::launch::async, [&, i] {
      const CameraMount& mount = opts.mounts[i];
      const DevelopedFrame frame = developMount(mount, robot, index);
      ImageRecord& record = out.records[i];
      record.file = cameraImageFileName(mount.label, index);
      record.label = mount.label;
      record.index = index;
      record.timestamp_s = mrpt::Clock::toDouble(stamp);
      record.effects = frameEffects(mount.label, index);
      record.quality = frame.quality;
      writeJpeg(images_dir_ / record.file, frame.image, opts.jpeg_quality);
    }));
  }
  for (auto& job : jobs) {
    job.get();  // rethrows OutputError from a job
  }
  for (const CameraMount& mount : opts.mounts) {
    out.observations.push_back(
        makeImageObservation(mount.label, pipeline_.intrinsics(), cameraMountPose(mount),
                             cameraImageFileName(mount.label, index), stamp));
  }
  return out;
}

}  // namespace pmap::sim
