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

std::string imageFileName(const std::string& label, int index) {
  char name[32];
  std::snprintf(name, sizeof(name), "_%06d.jpg", index);
  return label + name;
}

}  // namespace

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
      intrinsics_(PinholeIntrinsics::fromFov(world.sensors.cameras.width_px,
                                             world.sensors.cameras.height_px,
                                             degToRad(world.sensors.cameras.hfov_deg))),
      renderer_(world, posters, static_cast<std::uint32_t>(deriveSeed(seed, "textures"))) {}

cv::Mat CameraRig::renderMount(const CameraMount& mount, const Pose2D& robot) const {
  const RigidTransform cam = compose(toTransform(robot), toTransform(cameraMountPose(mount)));
  return renderer_.render(intrinsics_, cam);
}

std::vector<mrpt::obs::CObservation::Ptr> CameraRig::capture(const Pose2D& robot, int index,
                                                             mrpt::Clock::time_point stamp) const {
  const CameraOptions& opts = world_.sensors.cameras;
  // Each image depends only on (seed, label, index): rendering in parallel is deterministic.
  std::vector<std::future<void>> jobs;
  for (const CameraMount& mount : opts.mounts) {
    jobs.push_back(std::async(std::launch::async, [&, mount] {
      const cv::Mat clean = renderMount(mount, robot);
      const std::uint64_t noise_seed =
          deriveSeed(seed_, "image-noise:" + mount.label, static_cast<std::uint64_t>(index));
      writeJpeg(images_dir_ / imageFileName(mount.label, index),
                finishImage(clean, world_.noise.image_sigma, noise_seed), opts.jpeg_quality);
    }));
  }
  for (auto& job : jobs) {
    job.get();  // rethrows OutputError from a job
  }
  std::vector<mrpt::obs::CObservation::Ptr> out;
  for (const CameraMount& mount : opts.mounts) {
    out.push_back(makeImageObservation(mount.label, intrinsics_, cameraMountPose(mount),
                                       imageFileName(mount.label, index), stamp));
  }
  return out;
}

}  // namespace pmap::sim
