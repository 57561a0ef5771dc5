// A small software renderer for the simulated cameras: every rectangle is
// clipped to the near plane and projected to find its pixel bounding box; each
// pixel ray in that box is intersected with the rectangle's plane (holes and
// posters respected) and kept if nearer than the z-buffer. Cylinders and boxes
// are ray-cast the same way over their projected bounding box. Poster pixels
// average 2 x 2 samples over the pixel's area (posters carry pixel-scale
// detail); everything else is sampled at the pixel centre. Shading: a
// headlight term |n . ray| plus ambient. Output is BGR floats: the ideal
// optical image, before lens, blur, exposure and noise (frame_imaging.h).
#pragma once

#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "pmap/sim/camera_model.h"
#include "pmap/sim/world.h"

namespace pmap::sim {

class Renderer {
 public:
  /// `poster_images` (BGR, one per World::posters entry) and `world` must
  /// outlive the renderer. `texture_seed` varies the procedural textures.
  Renderer(const World& world, const std::vector<cv::Mat>& poster_images,
           std::uint32_t texture_seed);

  /// Renders a CV_32FC3 BGR image (values in [0, 255]); thread-safe.
  cv::Mat render(const PinholeIntrinsics& k, const RigidTransform& camera_to_world) const;

 private:
  struct Frame;
  void drawSurface(const Surface& s, Frame& f) const;
  /// True if p_world lies on one of the surface's posters or within margin_m of it.
  bool nearPoster(const Surface& s, const Eigen::Vector3d& p_world, double margin_m) const;
  void drawClutter(const Clutter& c, Frame& f) const;
  Eigen::Vector3f surfaceColour(const Surface& s, const Eigen::Vector3d& p_world,
                                const Eigen::Vector2d& local) const;

  const World& world_;
  const std::vector<cv::Mat>& posters_;
  std::uint32_t texture_seed_;
};

}  // namespace pmap::sim
