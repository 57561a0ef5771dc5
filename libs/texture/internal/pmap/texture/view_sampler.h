// Sampling one camera frame onto a tile: for every texel the frame sees
// (in front, inside the image, not occluded, within the distance and angle
// limits) its colour and its weight as a view:
//   w = cos(angle)^angle_power            (frontal views first)
//     * (1 - (d / max_distance)^2)^2      (near views first, 0 at the limit)
//     * smoothstep(border / feather_px)   (fades out towards the image border,
//                                          so that seams between views vanish)
//     * frame_weight                      (blur of the whole frame)
// (doc/textures.md).
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <opencv2/core.hpp>

#include "pmap/texture/camera_frame.h"
#include "pmap/texture/depth_buffer.h"
#include "pmap/texture/texture_options.h"
#include "pmap/texture/texture_tile.h"
#include "pmap/texture/view_geometry.h"

namespace pmap::texture {

struct FrameView {
  FrameView(const CameraFrame& f, const cv::Mat& img, const DepthBuffer* d, float g, double w,
            const TextureOptions& options)
      : frame(&f),
        image(&img),
        depth(d),
        gain(g),
        frame_weight(w),
        feather_px(options.feather_px * f.scale),
        cos_max_angle(std::cos(options.max_view_angle_deg * 0.017453292519943295)),
        bicubic(options.interpolation == "bicubic") {}

  const CameraFrame* frame;
  const cv::Mat* image;  ///< BGR 8-bit, frame->width x frame->height
  const DepthBuffer* depth;
  float gain;            ///< exposure gain applied to the colours
  double frame_weight;   ///< blur factor of the frame
  double feather_px;     ///< in this image's pixels
  double cos_max_angle;  ///< views more oblique are not used
  bool bicubic;          ///< sampled bicubic (else bilinear)
};

/// Bilinear BGR sample at (x, y) in pixel coordinates, inside the image.
cv::Vec3f sampleBilinear(const cv::Mat& bgr, double x, double y);

/// Bicubic BGR sample at (x, y) (Keys' cubic convolution, a = -0.5, the
/// image's border pixels repeated), clamped to [0, 255].
cv::Vec3f sampleBicubic(const cv::Mat& bgr, double x, double y);

/// The view weight of a sample (formula above); 0 when not usable.
double viewWeight(double cos_angle, double distance_m, double border_px, const FrameView& view,
                  const TextureOptions& options);

/// Colour and weight of `view` at the camera-frame point `c` owned by
/// `owner` with unit normal `n_cam` (camera frame; zero: no angle term).
/// Returns 0 when the view does not see it.
double sampleView(const Eigen::Vector3d& c, const Eigen::Vector3d& n_cam, std::int32_t owner,
                  const FrameView& view, const TextureOptions& options, cv::Vec3f& colour);

/// Calls sink(col, row, colour, weight) for every texel of `box` that the
/// view sees.
template <class Sink>
void sampleTile(const TextureTile& tile, const TexelBox& box, const FrameView& view,
                const TextureOptions& options, Sink&& sink) {
  const Eigen::Isometry3d& T = view.frame->world_to_camera;
  const Eigen::Vector3d n_cam = T.linear() * tile.normal;
  const Eigen::Vector3d du = T.linear() * (tile.u * (tile.length_u / tile.width));
  for (int row = box.row0; row <= box.row1; ++row) {
    Eigen::Vector3d c = T * tile.texelCentre(box.col0, row);
    for (int col = box.col0; col <= box.col1; ++col, c += du) {
      cv::Vec3f colour;
      const double w = sampleView(c, n_cam, tile.surface_id, view, options, colour);
      if (w > 0) {
        sink(col, row, colour, static_cast<float>(w));
      }
    }
  }
}

}  // namespace pmap::texture
