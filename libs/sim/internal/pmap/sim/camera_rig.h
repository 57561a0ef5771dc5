// The simulated cameras of a run: poster images (generated from the seed and
// written as PNG beside the camera images; they stay clean: they are the
// ground truth of the poster textures), a renderer, and capture() which renders
// every mount, develops it with the frame's imperfections (frame_imaging.h),
// writes JPEGs and returns the MRPT image observations (external storage, file
// names relative to PREFIX_Images/) with what the ground truth records.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <opencv2/core.hpp>
#include <vector>

#include <mrpt/core/Clock.h>
#include <mrpt/obs/CObservation.h>

#include "pmap/sim/camera_model.h"
#include "pmap/sim/frame_imaging.h"
#include "pmap/sim/renderer.h"
#include "pmap/sim/world.h"

namespace pmap::sim {

/// Generates one image per poster (seeded by `seed` and the poster id) and
/// writes each to `dir`/poster_<id>.png. Throws OutputError.
std::vector<cv::Mat> writePosterImages(const World& world, std::uint64_t seed,
                                       const std::filesystem::path& dir);

/// Encodes `image` as JPEG and writes it atomically. Throws OutputError.
void writeJpeg(const std::filesystem::path& path, const cv::Mat& image, int quality);

/// The images of every mount at one instant, in mount order.
struct Capture {
  std::vector<mrpt::obs::CObservation::Ptr> observations;
  std::vector<ImageRecord> records;
};

/// "<label>_<index, 6 digits>.jpg"
std::string cameraImageFileName(const std::string& label, int index);

class CameraRig {
 public:
  /// `world` and `posters` must outlive the rig. Throws ConfigError if the
  /// world's lens distortion cannot be rendered.
  CameraRig(const World& world, const std::vector<cv::Mat>& posters, std::uint64_t seed,
            std::filesystem::path images_dir);

  /// Image `index` of every mount at robot pose `robot`, time `stamp`. Each
  /// image depends only on (seed, label, index). Throws OutputError.
  Capture capture(const Pose2D& robot, int index, mrpt::Clock::time_point stamp) const;

  /// The noise-free, unblurred optical image of one mount (CV_32FC3, with the
  /// lens distortion, before vignetting and exposure).
  cv::Mat renderMount(const CameraMount& mount, const Pose2D& robot) const;
  /// The effects drawn for image `index` of camera `label`.
  FrameEffects frameEffects(const std::string& label, int index) const;
  /// Image `index` of `mount` as capture() writes it, without writing it.
  DevelopedFrame developMount(const CameraMount& mount, const Pose2D& robot, int index) const;

  /// Intrinsics of the images (with the lens distortion).
  const PinholeIntrinsics& intrinsics() const { return pipeline_.intrinsics(); }

 private:
  const World& world_;
  std::uint64_t seed_;
  std::filesystem::path images_dir_;
  ImagingPipeline pipeline_;
  Renderer renderer_;
};

}  // namespace pmap::sim
