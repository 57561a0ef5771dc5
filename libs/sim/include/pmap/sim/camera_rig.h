// The simulated cameras of a run: poster images (generated from the seed and
// written as PNG beside the camera images), a renderer, and capture() which
// renders every mount, adds noise, writes JPEGs and returns the MRPT image
// observations (external storage, file names relative to PREFIX_Images/).
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <opencv2/core.hpp>
#include <vector>

#include <mrpt/core/Clock.h>
#include <mrpt/obs/CObservation.h>

#include "pmap/sim/camera_model.h"
#include "pmap/sim/renderer.h"
#include "pmap/sim/world.h"

namespace pmap::sim {

/// Generates one image per poster (seeded by `seed` and the poster id) and
/// writes each to `dir`/poster_<id>.png. Throws OutputError.
std::vector<cv::Mat> writePosterImages(const World& world, std::uint64_t seed,
                                       const std::filesystem::path& dir);

/// Encodes `image` as JPEG and writes it atomically. Throws OutputError.
void writeJpeg(const std::filesystem::path& path, const cv::Mat& image, int quality);

class CameraRig {
 public:
  /// `world` and `posters` must outlive the rig.
  CameraRig(const World& world, const std::vector<cv::Mat>& posters, std::uint64_t seed,
            std::filesystem::path images_dir);

  /// Image `index` of every mount at robot pose `robot`, time `stamp`.
  std::vector<mrpt::obs::CObservation::Ptr> capture(const Pose2D& robot, int index,
                                                    mrpt::Clock::time_point stamp) const;

  /// Noise-free render of one mount (for tests).
  cv::Mat renderMount(const CameraMount& mount, const Pose2D& robot) const;

  const PinholeIntrinsics& intrinsics() const { return intrinsics_; }

 private:
  const World& world_;
  std::uint64_t seed_;
  std::filesystem::path images_dir_;
  PinholeIntrinsics intrinsics_;
  Renderer renderer_;
};

}  // namespace pmap::sim
